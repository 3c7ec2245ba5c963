#pragma once
// `orbit_trap.range: auto`: the range an orbit-trap material's value (trap or
// smooth iteration) takes over its fractals' surfaces, so that any palette
// spreads over the surface instead of sitting at its first colour.
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {

// The module's render plan with every automatic trap range filled in
// (trap_lo, trap_hi); materials with a range of their own are unchanged.
ir::RenderPlan with_trap_ranges(const ir::Module& m);

}  // namespace sdfc::codegen::detail
