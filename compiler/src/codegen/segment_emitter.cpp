// The direct integrator's entry functions: one ray segment (march, shading
// at the hit or the background, the per-segment effects) and the radiance
// of one camera ray with its reflection bounces.
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "entry_emitters.hpp"
#include "object_set_emitter.hpp"
#include "shading_emitter.hpp"

namespace sdfc::codegen::detail {

// Clips the ray to the scene's bounds (the box, and a fractal's bounding
// ball) as t0, t1; false for an unbounded scene (nothing emitted).
bool bounds_clip(CodeWriter& w, const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  const auto& bounds = m.analyses.ray_bounds;
  if (!bounds) return false;
  const ir::Box3& b = bounds->box;
  used.insert("ray_box");
  w.line("// march only where the ray crosses the scene's bounds (inferred from the IR)");
  w.line("real t0, t1;");
  w.line(fmt::format("active = active & ray_box(ro, rd, {}, {}, &t0, &t1);", lit.vec3(b.lo), lit.vec3(b.hi)));
  if (bounds->has_sphere) {
    used.insert("ray_sphere");
    w.line("// and inside the fractal's bounding ball");
    w.line("real s0, s1;");
    w.line(fmt::format("active = active & ray_sphere(ro, rd, {}, {}, &s0, &s1);", lit.vec3(bounds->center),
                       lit.real(bounds->radius)));
    w.line("t0 = fmax(t0, s0);");
    w.line("t1 = fmin(t1, s1);");
  }
  return true;
}

// One ray segment: bounds, march, shading at the hit, background on a miss,
// and the effects that belong to a segment (AO, glow, fog). The primary ray
// and every reflection bounce run through it.
std::string segment_function(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  const bool blended = m.analyses.material_blend;
  const ir::MarchSettings& s = m.plan.march;
  const ir::Effects& fx = m.plan.effects;
  bool any_shadows = false;
  for (const auto& l : m.plan.lights) any_shadows |= l.shadows != ir::Light::Shadows::None;
  CodeWriter w;
  w.line("// ---- one ray segment: march, then shade the hit or the background ----");
  const bool cones = camera_cones(m);
  w.line(fmt::format("vec3 sdfc_segment(TIME_PARAM vec3 ro, vec3 rd, mask active, real pixel_angle, real jitter,{}{}",
                     fx.glow.enabled ? " real glow_weight," : "", cones ? " const os_cone cone," : ""));
  const bool refl_out = blended && fx.reflections.depth > 0;
  w.line(fmt::format("                  real* t_out, mask* hit_out, vec3* n_out, real* mat_out, real* steps_out{})",
                     refl_out ? ", real* refl_out" : ""));
  w.open("{");
  if (bounds_clip(w, m, lit, used)) {
    w.line(fmt::format("t1 = fmin(t1, {});", lit.real(s.max_distance)));
  } else {
    w.line("// the scene is unbounded (it holds a plane): march the whole range");
    w.line("real t0 = 0.0f;");
    w.line(fmt::format("real t1 = {};", lit.typed(s.max_distance)));
  }
  if (s.dither) {
    w.line("// render.dither: a random fraction of the first step against banding");
    w.line(fmt::format("t0 = t0 + jitter * {} * fmax(scene_dist(TIME_ARG v3_mad(ro, rd, t0)), K(0.0f));", lit.real(s.step_factor)));
  } else {
    w.line("(void)jitter;");
  }
  if (m.analyses.ray_bounds || s.dither) w.line("active = active & (t0 < t1);  // render.max_distance from the first step on");
  w.line("real t, steps;");
  if (s.refine == ir::MarchSettings::Refine::Bisection) {
    used.insert("march_sphere_trace_refined");
    w.line("// render.refine: bisection - bracket the surface after the hit and bisect it");
    w.line("real closest;");
    w.line(fmt::format("mask hit = march_sphere_trace_refined(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps, &closest);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
    if (!fx.glow.enabled) w.line("(void)closest;");
  } else if (fx.glow.enabled) {
    used.insert("march_sphere_trace_closest");
    w.line("real closest;");
    w.line(fmt::format("mask hit = march_sphere_trace_closest(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps, &closest);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  } else if (cones) {
    used.insert("march_sphere_trace_cone");
    w.line("// camera rays count only the object sets' items in their packet's cone (os_cone)");
    w.line(fmt::format("mask hit = march_sphere_trace_cone(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps, cone);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  } else {
    used.insert("march_sphere_trace");
    w.line(fmt::format("mask hit = march_sphere_trace(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  }
  w.line(fmt::format("vec3 color = {};", background_call(m.plan, lit, used)));
  w.line("vec3 n = v3_splat(0.0f);");
  w.line("real mat = -1.0f;");
  if (refl_out) w.line("real refl = 0.0f;");
  w.line("if (M_ANY(hit))");
  w.open("{");
  w.line("// shading runs once per packet with a hit, never inside the march");
  w.line("vec3 pos = v3_mad(ro, rd, t);");
  if (s.normal_step == 0.5 && s.normal_step_floor == 1e-6)
    w.line("real h = fmax(pixel_angle * t * 0.5f, K(1e-6f));  // finite-difference step: half a pixel footprint");
  else
    w.line(fmt::format("real h = fmax(pixel_angle * t * {}, K({}));  // render.normal_step: {} pixel footprints",
                       lit.real(s.normal_step), lit.real(s.normal_step_floor), s.normal_step));
  // With an object set the material comes first: its distance at the hit
  // bounds the normals' taps, so their walks open only the nearby boxes.
  // Only the hits' lanes open the set's boxes, and the packet's list answers for it where it can.
  const bool below = bounded_shading(m);
  if (s.normals == ir::NormalMethod::Dual) {
    w.line("n = scene_normal_dual(pos);  // exact gradient by forward-mode differentiation");
  } else if (below) {
    if (shading_from_list(m)) {
      used.insert("os_cone_shading");
      w.line("const os_cone shade = os_cone_shading(cone);  // the set's items beside the rays, where the list holds them");
    } else {
      w.line("const os_cone shade = os_cone_none();");
    }
    w.line("real id;");
    emit_bounded_hit(w, m, lit, used, "shade");
  } else {
    const char* normal_fn = s.normals == ir::NormalMethod::Central ? "normal_central" : "normal_tetrahedral";
    used.insert(normal_fn);
    w.line(fmt::format("n = {}(TIME_ARG pos, h);", normal_fn));
  }
  std::string extra;
  if (below) {
    // the material came with d_hit
  } else if (blended) {
    w.line("real id;");
    w.line("mat_record look;  // the materials mixed across smooth blends");
    w.line(m.analyses.coloring_geometry ? "id = scene_material(TIME_ARG pos, n, &look);" : "id = scene_material(TIME_ARG pos, &look);");
    if (refl_out) w.line("refl = SEL(refl, look.reflectivity, hit);");
  } else if (const auto& uni = m.analyses.uniform_material) {
    w.line(fmt::format("real id = {};  // the scene's one material: no distance evaluation needed", lit.typed(*uni)));
  } else {
    w.line("real id;");
    w.line("(void)scene_dist_mat(TIME_ARG pos, &id);");
  }
  w.line("mat = SEL(mat, id, hit);");
  if (m.analyses.orbit_traps && !blended) {
    w.line("real trap = scene_trap(TIME_ARG pos);  // orbit-trap colour, once per hit");
    extra += ", trap";
  }
  if (fx.ambient_occlusion.enabled) {
    const auto& ao = fx.ambient_occlusion;
    if (ao.method == ir::AmbientOcclusion::Method::NormalSamples) {
      used.insert("ao_normal_samples");
      w.line(fmt::format("// effects.ambient_occlusion: {} probes along the normal", ao.samples));
      w.line(fmt::format("real occlusion = ao_normal_samples(TIME_ARG pos, n, {}, {}, {}, hit);", ao.samples, lit.real(ao.distance),
                         lit.real(ao.strength)));
    } else {
      used.insert("ao_step_count");
      w.line("// effects.ambient_occlusion: from the march's step count");
      w.line(fmt::format("real occlusion = ao_step_count(steps, {}, {});", lit.real(s.max_steps), lit.real(ao.strength)));
    }
    extra += ", occlusion";
  }
  if (any_shadows) extra += ", h, hit";
  if (!any_shadows) w.line("(void)h;");
  w.line(fmt::format("vec3 lit = shade_surface(TIME_ARG pos, n, v3_scale(rd, -1.0f), {}{});",
                     blended ? "look.albedo, look.specular, look.shininess" : "id", extra));
  w.line("color = v3_select(color, lit, hit);");
  w.close("}");
  if (fx.glow.enabled) {
    const auto& g = fx.glow;
    w.line("// effects.glow: near misses glow by their closest approach, every ray by its step count;");
    w.line("// camera rays only (glow_weight 0 on bounces, whose closest approach is the surface they leave)");
    w.line(fmt::format("real near = clamp(1.0f - closest / {}, K(0.0f), K(1.0f));", lit.real(g.radius)));
    w.line(fmt::format("real glow = SEL((real)(0.0f), {} * near * near, !hit) + {} * steps / {};", lit.real(g.strength),
                       lit.real(g.step_strength), lit.real(s.max_steps)));
    w.line(fmt::format("color = v3_mad(color, {}, glow * glow_weight);", lit.vec3(g.color)));
  }
  if (fx.fog.enabled) {
    const auto& f = fx.fog;
    w.line("// effects.fog: misses count as reaching max_distance");
    w.line(fmt::format("real fog_t = SEL((real)({}), t, hit);", lit.real(s.max_distance)));
    if (f.height_falloff > 0) {
      used.insert("fog_height");
      w.line(fmt::format("color = fog_height(color, {}, ro, rd, fog_t, {}, {}, {}, {});", lit.vec3(f.color),
                         lit.vec3(m.plan.camera.up), detail::animated(f.density_anim, f.density, lit), lit.real(f.height_falloff), lit.real(f.base_height)));
    } else {
      used.insert("fog_exponential");
      w.line(fmt::format("color = fog_exponential(color, {}, fog_t, {});", lit.vec3(f.color), detail::animated(f.density_anim, f.density, lit)));
    }
  }
  // a miss's normal is 0 (the normal AOV); the lanes that missed in a packet with hits computed one
  w.line(fmt::format("*t_out = t; *hit_out = hit; *n_out = v3_select(v3_splat(0.0f), n, hit); *mat_out = mat; *steps_out = steps;{}",
                     refl_out ? " *refl_out = refl;" : ""));
  w.line("return color;");
  w.close("}");
  return w.take();
}

// The colour seen along one camera ray: the primary segment and, with
// effects.reflections, a bounded loop of mirror bounces weighted by
// Fresnel-Schlick (no recursion in OpenCL C).
std::string radiance_function(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  const bool blended = m.analyses.material_blend;
  const bool cones = camera_cones(m);
  const int depth = m.plan.effects.reflections.depth;
  const bool glow = m.plan.effects.glow.enabled;
  CodeWriter w;
  w.line("// ---- the colour along one camera ray; the AOVs of its first hit ----");
  w.line("vec3 sdfc_radiance(TIME_PARAM vec3 ro, vec3 rd, real pixel_angle, real jitter,");
  w.line("                   real* depth, vec3* normal, real* mat, real* steps)");
  w.open("{");
  w.line("real t;");
  w.line("mask hit;");
  // blended: the segment hands back the mixed reflectivity, not only an id
  const bool refl = blended && depth > 0;
  if (refl) w.line("real refl;");
  std::string refl_arg = refl ? ", &refl" : "";
  if (cones) {
    used.insert("os_camera_cone");
    w.line("// the camera rays' cone: every lane's ray leaves the pinhole, and the hit band around it");
    const std::string gather = camera_list_gather(m);
    // the list's cone is wider by the farthest normal tap's angle (sqrt(3) h for the tetrahedral taps)
    const double tap = m.plan.march.normal_step * (m.plan.march.normals == ir::NormalMethod::Central ? 1.0 : std::sqrt(3.0));
    w.line(fmt::format("{}os_cone cone = os_camera_cone(ro, rd, pixel_angle * {}, {});", gather.empty() ? "const " : "",
                       lit.real(m.plan.march.hit_epsilon),
                       shading_from_list(m) ? "pixel_angle * " + lit.real(tap) : std::string("0.0f")));
    if (!gather.empty()) {
      used.insert("os_list");
      w.line("os_list list;  // the object set's items in the cone, in order along it: the camera march measures these");
      w.line(gather);
      w.line("cone.list = &list;");
    }
  }
  w.line(fmt::format("vec3 color = sdfc_segment(TIME_ARG ro, rd, M_TRUE, pixel_angle, jitter,{}{} &t, &hit, normal, mat, steps{});",
                     glow ? " 1.0f," : "", cones ? " cone," : "", refl_arg));
  w.line("*depth = SEL((real)(-1.0f), t, hit);  // -1 marks a miss");
  if (depth > 0) {
    used.insert("fresnel_schlick");
    w.line(fmt::format("// effects.reflections: up to {} bounce(s)", depth));
    w.line("vec3 weight = v3_splat(1.0f), sum = v3_splat(0.0f), n = *normal;");
    w.line("real id = *mat;");
    w.line("mask alive = hit;");
    w.line("vec3 seg = color;");
    w.line(fmt::format("for (int bounce = 0; bounce < {} && M_ANY(alive); ++bounce)", depth));
    w.open("{");
    std::string r0 = refl ? "refl" : "material_reflectivity(id)";
    w.line(fmt::format("real f = fresnel_schlick({}, -v3_dot(rd, n));", r0));
    w.line(fmt::format("alive = alive & ({} > 0.0f);", r0));
    w.line("// the surface keeps 1 - F of its own colour; F goes to what it reflects");
    w.line("real keep = SEL((real)(1.0f), 1.0f - f, alive);");
    w.line("sum = v3_add(sum, v3_mul(weight, v3_scale(seg, keep)));");
    w.line("weight = v3_select(v3_splat(0.0f), v3_scale(weight, f), alive);");
    w.line("if (!M_ANY(alive)) break;");
    w.line("vec3 p = v3_mad(ro, rd, t);");
    w.line("real footprint = fmax(pixel_angle * t, K(1e-5f));");
    w.line("ro = v3_mad(p, n, 2.0f * footprint);");
    w.line("rd = v3_normalize(v3_mad(rd, n, -2.0f * v3_dot(rd, n)));");
    w.line("real s;");
    w.line(fmt::format("seg = sdfc_segment(TIME_ARG ro, rd, alive, pixel_angle, (real)(0.0f),{}{} &t, &hit, &n, &id, &s{});",
                       glow ? " 0.0f," : "", cones ? " os_cone_none()," : "", refl_arg));
    w.line("alive = alive & hit;");
    w.close("}");
    w.line("color = v3_add(sum, v3_mul(weight, seg));  // the last segment counts in full");
  }
  w.line("return color;");
  w.close("}");
  return w.take();
}

}  // namespace sdfc::codegen::detail
