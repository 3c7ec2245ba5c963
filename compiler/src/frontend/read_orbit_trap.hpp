#pragma once
// A material's `orbit_trap:` colour controls (docs/scene-format.md, "Orbit-trap colour").
#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_orbit_trap(ValueReader& r, const SourceValue& v, ir::MaterialDef& md);
}  // namespace sdfc::frontend
