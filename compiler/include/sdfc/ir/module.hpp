#pragma once
#include <memory>
#include <string>

#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::ir {

// What passes take and return: the geometry DAG, its root and the plan.
struct Module {
  std::shared_ptr<Graph> graph = std::make_shared<Graph>();
  NodeId root = kNoNode;
  RenderPlan plan;
  std::string source_name;  // the scene file, for comments in the kernel
};

}  // namespace sdfc::ir
