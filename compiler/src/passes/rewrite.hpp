#pragma once
// Shared by the rewriting passes: rebuild a module's DAG bottom-up into a
// fresh graph, letting a rule decide what each node becomes. Every node goes
// through the hash-consing Builder, so the result is deduplicated too.
#include <functional>
#include <vector>

#include "sdfc/ir/module.hpp"

namespace sdfc::passes::detail {

// rule(builder, original node, already-rewritten children) -> new node id
using Rule = std::function<ir::NodeId(ir::Builder&, const ir::Node&, std::vector<ir::NodeId>)>;
ir::Module rewrite(ir::Module m, const Rule& rule);

// The folding rules, applied to one node whose children are already folded.
// canonicalise reuses it so its reorderings fold as they are made.
ir::NodeId fold_node(ir::Builder& b, ir::Kind k, std::vector<double> params, std::vector<ir::NodeId> kids,
                     const SourceLoc& loc,
                     ir::Animation anim = {});

}  // namespace sdfc::passes::detail
