#pragma once
// A material's `orbit_trap:` colour controls (docs/scene-format.md, "Orbit-trap colour").
#include <string>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_orbit_trap(ValueReader& r, const SourceValue& v, ir::MaterialDef& md);
// `coloring:` several sources mixed (read_coloring.cpp).
void read_coloring(ValueReader& r, const SourceValue& v, ir::MaterialDef& md);

// The keys shared with `coloring:` sources: how a value walks its palette
// (palette or gradient, range, offset, cycles, repeat), and a trap's shape.
void read_palette_walk(ValueReader& r, MapReader& m, const std::string& what, ir::ColourSource& s);
void read_trap_shape(ValueReader& r, MapReader& m, const std::string& what, ir::TrapShape& t);
}  // namespace sdfc::frontend
