#pragma once
// Making an IR node from parameters that may be animated: the values at
// time 0 go to the node's params, the expressions of time to its animation.
#include <vector>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::frontend {

inline ir::NodeId make_node(ir::Builder& b, ir::Kind k, const std::vector<Param>& params,
                            std::vector<ir::NodeId> children, const SourceLoc& at) {
  std::vector<double> values;
  ir::Animation anim;
  for (const Param& p : params) values.push_back(p.value), anim.push_back(p.anim);
  return b.make(k, std::move(values), std::move(children), at, std::move(anim));
}

}  // namespace sdfc::frontend
