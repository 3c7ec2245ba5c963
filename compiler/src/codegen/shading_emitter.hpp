#pragma once
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/analyses.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
// Emits material_of() (a select chain over the plan's materials) and
// shade_surface() (ambient folded to one constant, then one Blinn-Phong
// term per light, unrolled with its values as literals). blended: the
// scene mixes materials (scene_material), so shade_surface takes the mixed
// albedo, specular and shininess instead of a material id.
// Shadow rays end where they leave the scene's ray bounds (facts.ray_bounds).
std::string emit_shading(const ir::RenderPlan& plan, const ir::Analyses& facts, const Literals& lit,
                         std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
