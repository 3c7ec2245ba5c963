#pragma once
// The kernel's entry-point functions, one emitter per file: the ray segment
// and the radiance of one camera ray (segment_emitter.cpp, the direct
// integrator), the path integrator (path_emitter.cpp) and the render kernel
// that places the samples (render_kernel_emitter.cpp).
#include <functional>
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {

// Clips the ray to the scene's bounds as t0, t1 (segment_emitter.cpp);
// false, emitting nothing, for an unbounded scene.
bool bounds_clip(CodeWriter& w, const ir::Module& m, const Literals& lit, std::set<std::string>& used);
std::string segment_function(const ir::Module& m, const Literals& lit, std::set<std::string>& used);
std::string radiance_function(const ir::Module& m, const Literals& lit, std::set<std::string>& used);
// The path integrator's functions (render.integrator: path): the material
// table, the path's materials, sdfc_path_hit and sdfc_path. plan: the
// module's plan with the orbit traps' measured ranges.
// Whether any material has a GGX lobe (roughness or metalness) or emission,
// and path_surface() for them (path_surface_emitter.cpp).
bool any_glossy(const ir::RenderPlan& p);
bool any_emission(const ir::RenderPlan& p);
bool any_glass(const ir::RenderPlan& p);
std::string surface_table(const ir::RenderPlan& plan, bool glossy, bool emission, bool glass, const Literals& lit);
// A glass vertex's scattering (path_glass_emitter.cpp): Fresnel picks the
// reflected or refracted direction of the lanes on glass, into nd, and the
// side of the surface the next segment starts on.
void glass_scatter(CodeWriter& w);
// aovs: sdfc_path also returns the first hit's albedo (1 on glass).
std::string path_functions(const ir::Module& m, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used,
                           bool aovs);
// The background or sky along `rd`, as an expression (background_emitter.cpp).
std::string background_call(const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used);
// background.map with the path integrator (path_env_emitter.cpp): whether
// the kernel takes the map, the map's radiance where a path escapes (into
// `env`, MIS-weighted by the last bounce's density pdf_b unless `delta`), and
// a light sample drawn from the map at a vertex, added through `add` for `lanes`.
bool env_map_used(const ir::RenderPlan& plan);
void env_escape(CodeWriter& w, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used);
void env_light(CodeWriter& w, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used,
               const ir::RayBounds* bounds, bool glossy, const std::string& lanes,
               const std::function<void(const std::string&, const std::string&, const std::string&)>& add);
std::string render_kernel(const ir::Module& m, const Literals& lit, std::set<std::string>& used, const EmitOptions& opt);

}  // namespace sdfc::codegen::detail
