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
// material_of() and, with reflections, material_reflectivity(): the part of
// emit_shading that the path integrator shares.
std::string emit_material_table(const ir::RenderPlan& plan, const ir::Analyses& facts, const Literals& lit);
// The shadow factor towards a light as a call (empty when it casts none);
// the caller's scope holds shadow_origin, footprint, hit and n.
// A point light's position, as literals or, where animated, expressions of time.
std::string light_position(const ir::Light& l, const Literals& lit);
// `open` (facts.shadow_bounds, or null) lets rays that rise from the scene's
// planes stop early (shadow_soft_open); `fixed` is the direction to the light
// when the build knows it.
std::string shadow_call(const ir::Light& l, const std::string& to_light, std::string tmax, const Literals& lit,
                        const ir::RayBounds* bounds, std::set<std::string>& used,
                        const ir::ShadowBounds* open = nullptr, const ir::Vec3d* fixed = nullptr);
std::string emit_shading(const ir::RenderPlan& plan, const ir::Analyses& facts, const Literals& lit,
                         std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
