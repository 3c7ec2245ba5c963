#pragma once
// A node being rebuilt by fold_constants (and by canonicalise, which folds
// what it moves): what a description's `fold` hook sees.
#include <functional>
#include <vector>

#include "sdfc/ir/graph.hpp"

namespace sdfc::kinds {

struct Folding {
  const ir::Graph& g;
  const std::vector<double>& params;
  const std::vector<ir::NodeId>& kids;
  // Neither the node nor its first child is animated, so the two may merge.
  bool merge;
  // Builds (and folds again) a node of the same kind at the same place.
  std::function<ir::NodeId(std::vector<double> params, std::vector<ir::NodeId> kids)> again;
  const ir::Node& child(size_t i) const { return g.node(kids[i]); }
};

}  // namespace sdfc::kinds
