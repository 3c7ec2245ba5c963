#pragma once
// The hybrid's parameters and its orbit loop, written inline in the kernel
// (its estimator and its orbit trap / smooth iteration count).
#include "fractal.hpp"

namespace sdfc::kinds::hybrid {

// One step: a Mandelbulb power, or a Mandelbox scale and its fold's radii.
struct StepP {
  double formula;         // an ir::HybridStep code
  double repeat;          // how many times in a row it runs
  double power_or_scale;  // the bulb's power, or the box's scale
  double min_radius, fixed_radius, folding_limit;  // box steps only
};
struct HybridP {
  double iterations, bailout, steps;  // steps: how many of `step` are used
  std::array<StepP, ir::kHybridMaxSteps> step;
};
static_assert(sizeof(StepP) == ir::kHybridStepParams * sizeof(double));

// The estimator's code; returns the variable holding the distance.
std::string emit(Emitter& e);
// The orbit trap (e.shape's measure) or the smooth iteration count.
std::string emit_trap(Emitter& e);

}  // namespace sdfc::kinds::hybrid
