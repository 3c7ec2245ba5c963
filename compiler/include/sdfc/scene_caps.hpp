#pragma once
// Caps on what a scene may cost, so a shared scene file cannot hang the
// machine: the estimated work per sample (docs/security.md). The command
// line raises them (--allow-slow); a scene file cannot.
#include "sdfc/ir/module.hpp"

namespace sdfc {

struct SceneCaps {
  // Rough flops per camera sample. The examples need up to ~1e6; at 1e8 the
  // smallest launch (one packet of 16 samples) still ends within seconds,
  // so Ctrl-C works.
  double max_cost_per_sample = 1e8;
  bool allow_slow = false;  // --allow-slow: no cost cap
};

// The process's caps (the CLI sets them from its options before compiling).
SceneCaps& scene_caps();

// Scene evaluations per sample (march steps, shadow rays, occlusion probes,
// bounces) times the flops of one evaluation.
double estimated_cost_per_sample(const ir::Module& m);

// Throws a SceneError at the scene's root with the estimate and the cap
// when the estimate is over it (and --allow-slow was not given).
void check_scene_cost(const ir::Module& m);

}  // namespace sdfc
