#pragma once
#include <memory>
#include <string>

#include "sdfc/ir/analyses.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::ir {

// What passes take and return: the geometry DAG, its root and the plan.
struct Module {
  std::shared_ptr<Graph> graph = std::make_shared<Graph>();
  NodeId root = kNoNode;
  RenderPlan plan;
  std::string source_name;  // the scene file, for comments in the kernel
  Analyses analyses;        // recorded by the analyse pass, read by the emitters
  int unlocked = 0;         // values the kernel reads after the frame block (sdfc/source/unlock.hpp)
};

}  // namespace sdfc::ir
