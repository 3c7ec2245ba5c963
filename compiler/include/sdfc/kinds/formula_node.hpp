#pragma once
// The chain a `formula` node stands for (the node holds its index in the
// chain table; this is the one place that reads it).
#include "sdfc/formula/chain.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::kinds {

const formula::Chain& chain_of(const ir::Node& formula_node);

}  // namespace sdfc::kinds
