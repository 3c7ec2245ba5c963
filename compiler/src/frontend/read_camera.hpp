#pragma once
// The scene's `camera:` section (docs/scene-format.md, "camera").
#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_camera(ValueReader& r, const SourceValue& v, ir::Camera& cam);
// A view direction must exist and must not run along the up vector.
void check_view(ValueReader& r, const SourceLoc& loc, const SourceLoc& up_loc, const Vec3d& position, const Vec3d& target,
                const Vec3d& up, const std::string& what);
}  // namespace sdfc::frontend
