#pragma once
// The scene's `camera:` section (docs/scene-format.md, "camera").
#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_camera(ValueReader& r, const SourceValue& v, ir::Camera& cam);
}  // namespace sdfc::frontend
