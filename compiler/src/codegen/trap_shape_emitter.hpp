#pragma once
// The orbit trap's shape (`orbit_trap.shape`). The default (cross: the
// nearest coordinate plane) is written into the stdlib's trap functions. Any
// other shape gets, per material, a measure function (`orbit_trap_m<i>`) and
// copies of the stdlib trap functions its fractals use that call it in place
// of the default measure, so a kernel holds only the shapes its materials
// chose, and a scene with the default trap the same code as before shapes.
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {

// True when material i's trap has a shape other than the default.
bool shaped_trap(const ir::RenderPlan& plan, size_t material);

// The call of material i's measure on the orbit point `z` (registering the
// measure function in `used`), for traps written inline (the hybrid).
std::string trap_measure_call(size_t material, const std::string& z, std::set<std::string>& used);

// The name of stdlib trap function `fn` specialised to material i's shape,
// registering the copy in `used`.
std::string shaped_trap_fn(const std::string& fn, size_t material, std::set<std::string>& used);

// Takes the registrations out of `used` (adding the stdlib functions the
// copies call) and returns the measure functions and the copies, to follow
// the stdlib in the kernel; "" when nothing was registered.
std::string emit_trap_shapes(const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used);

}  // namespace sdfc::codegen::detail
