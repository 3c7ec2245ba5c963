#pragma once
// Orbit-trap colour: a material's value (trap or smooth iteration) mapped
// onto its palette or gradient.
#include <cstddef>

#include "code_writer.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {

// Writes, inside material_of, the statements that mix material i's palette
// colour for the kernel variable `trap` into *albedo where `is{i}` holds.
void emit_trap_palette(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i);

}  // namespace sdfc::codegen::detail
