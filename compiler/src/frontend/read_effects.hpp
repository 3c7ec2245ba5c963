#pragma once
// The scene's `effects:` section (docs/scene-format.md, "Effects").
#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_effects(ValueReader& r, const SourceValue& v, ir::Effects& fx);
}  // namespace sdfc::frontend
