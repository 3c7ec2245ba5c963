#pragma once
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
// Emits material_of() (a select chain over the plan's materials) and
// shade_surface() (ambient folded to one constant, then one Blinn-Phong
// term per light, unrolled with its values as literals). blended: the
// scene mixes materials (scene_material), so shade_surface takes the mixed
// albedo, specular and shininess instead of a material id.
// Where rays can meet the scene: its padded bounding box and, when the
// compiler knows one (a lone Mandelbulb), a tighter bounding sphere.
struct RayBounds {
  ir::Box3 box;
  bool has_sphere = false;
  ir::Vec3d center{0, 0, 0};
  double radius = 0;
};
// bounds: null when the scene is unbounded; otherwise shadow rays end there.
std::string emit_shading(const ir::RenderPlan& plan, const Literals& lit, const RayBounds* bounds,
                         std::set<std::string>& used, bool blended);
}  // namespace sdfc::codegen::detail
