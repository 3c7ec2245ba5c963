#pragma once
// Palette colour: a material's value (orbit trap, smooth iteration, or for
// `coloring:` also the normal or the position) mapped onto its palette or
// gradient, and several sources mixed by weight.
#include <cstddef>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {

// The statements that declare `vec3 pal`, source s's colour for the kernel
// expression `value`.
void emit_palette_lookup(CodeWriter& w, const Literals& lit, const ir::ColourSource& s, const std::string& value);

// Inside material_of: material i's palette colour for the kernel variable
// `trap`, mixed into *albedo where `is{i}` holds.
void emit_trap_palette(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i);

// Inside material_of: material i's `coloring:` sources (the orbit value in
// `trap`, the hit in `p` and `n`), mixed into *albedo where `is{i}` holds.
void emit_coloring(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i);

}  // namespace sdfc::codegen::detail
