#pragma once
#include <string>

#include "sdfc/ir/module.hpp"

namespace sdfc::ir {
struct PrintOptions {
  bool props = true;  // append bounds / class / L / cost when inferred
  bool plan = true;   // print the render plan after the DAG
};
// Stable text form: nodes numbered %0.. in postorder, one per line; used by
// `--emit ir`, `--dump-after` and the golden tests.
std::string print(const Module& m, const PrintOptions& opt = {});
std::string print_plan(const RenderPlan& plan);
size_t count_nodes(const Module& m);  // reachable from the root
}  // namespace sdfc::ir
