#include "shading_emitter.hpp"

#include <fmt/format.h>

#include "palette_emitter.hpp"
#include "kernel_text.hpp"

namespace sdfc::codegen::detail {

namespace {

std::string where(const SourceLoc& loc) {
  if (loc.line <= 0) return "built-in";
  std::string f = loc.file ? *loc.file : "";
  size_t slash = f.find_last_of('/');
  if (slash != std::string::npos) f = f.substr(slash + 1);
  return fmt::format("{}:{}", kernel_text(f), loc.line);
}

}  // namespace

// The shadow factor towards a light (empty when the light casts none).
// With the scene's bounds, the march stops where the shadow ray leaves them:
// nothing beyond can block the light.
std::string light_position(const ir::Light& l, const Literals& lit) {
  if (!l.position_anim[0] && !l.position_anim[1] && !l.position_anim[2]) return lit.vec3(l.position);
  return fmt::format("v3({}, {}, {})", animated(l.position_anim[0], l.position[0], lit),
                     animated(l.position_anim[1], l.position[1], lit), animated(l.position_anim[2], l.position[2], lit));
}

// The lanes whose shadow ray rises from every plane of `open` steeply enough
// that no plane can block it (hard shadows: at all) or lower its penumbra
// k d / t below 1 (soft: a slope of at least 1/k): "M_TRUE" when the build
// knows the direction (`fixed`, a directional light) and it does, "" when it
// does not, else a per-lane test.
std::string rising_lanes(const ir::Light& l, const std::string& to_light, const ir::Vec3d* fixed,
                         const ir::ShadowBounds& open, const Literals& lit) {
  const double k = l.shadows == ir::Light::Shadows::Soft ? l.softness : 0.0;
  std::string tests;
  for (const ir::Vec3d& n : open.plane_normals) {
    if (fixed) {
      const double slope = (*fixed)[0] * n[0] + (*fixed)[1] * n[1] + (*fixed)[2] * n[2];
      if (k > 0 ? k * slope < 1.0 : slope <= 0.0) return "";
      continue;
    }
    tests += tests.empty() ? "" : " & ";
    tests += k > 0 ? fmt::format("({} * v3_dot({}, {}) >= 1.0f)", lit.real(k), to_light, lit.vec3(n))
                   : fmt::format("(v3_dot({}, {}) > 0.0f)", to_light, lit.vec3(n));
  }
  return tests.empty() ? "M_TRUE" : tests;
}

std::string shadow_call(const ir::Light& l, const std::string& to_light, std::string tmax, const Literals& lit,
                        const ir::RayBounds* bounds, std::set<std::string>& used, const ir::ShadowBounds* open,
                        const ir::Vec3d* fixed) {
  if (l.shadows == ir::Light::Shadows::None) return "";
  const std::string rising = open ? rising_lanes(l, to_light, fixed, *open, lit) : "";
  if (!rising.empty() && l.shadows == ir::Light::Shadows::Hard) {
    // A rising hard shadow ray is blocked by nothing past the parts' box.
    used.insert("ray_box_exit");
    std::string exit = fmt::format("ray_box_exit(shadow_origin, {}, {}, {}, {})", to_light, lit.vec3(open->box.lo),
                                   lit.vec3(open->box.hi), tmax);
    tmax = rising == "M_TRUE" ? exit : fmt::format("SEL({}, {}, {})", tmax, exit, rising);
  }
  if (bounds) {
    used.insert("ray_box_exit");
    tmax = fmt::format("ray_box_exit(shadow_origin, {}, {}, {}, {})", to_light, lit.vec3(bounds->box.lo),
                       lit.vec3(bounds->box.hi), tmax);
    if (bounds->has_sphere) {
      used.insert("ray_sphere_exit");
      tmax = fmt::format("ray_sphere_exit(shadow_origin, {}, {}, {}, {})", to_light, lit.vec3(bounds->center),
                         lit.real(bounds->radius), tmax);
    }
  }
  std::string common = "shadow_origin, " + to_light + ", 2.0f * footprint, " + tmax;
  // only lanes that hit and face the light march
  std::string tail = fmt::format("footprint, 0.5f * footprint, {}, hit & (v3_dot(n, {}) > 0.0f)", l.shadow_steps, to_light);
  if (l.shadows == ir::Light::Shadows::Hard) {
    used.insert("shadow_hard");
    return fmt::format("shadow_hard(TIME_ARG {}, {})", common, tail);
  }
  if (!rising.empty()) {
    used.insert("shadow_soft_open");
    return fmt::format("shadow_soft_open(TIME_ARG {}, {}, {}, {}, {}, {})", common, lit.real(l.softness), tail,
                       lit.vec3(open->box.lo), lit.vec3(open->box.hi), rising);
  }
  used.insert("shadow_soft");
  return fmt::format("shadow_soft(TIME_ARG {}, {}, {})", common, lit.real(l.softness), tail);
}

std::string emit_material_table(const ir::RenderPlan& plan, const ir::Analyses& facts, const Literals& lit) {
  const bool blended = facts.material_blend;
  CodeWriter w;
  const auto& mats = plan.materials;
  const bool traps = facts.orbit_traps;  // any orbit-trap material: the trap value comes along
  std::string trap_param = traps ? ", real trap" : "";
  // a coloring source reads the hit's position and normal (world space)
  const std::string geometry_param = facts.coloring_geometry ? ", vec3 p, vec3 n" : "";
  w.line("// ---- materials: id -> albedo, specular, shininess ----");
  w.line("void material_of(real id, vec3* albedo, real* specular, real* shininess" + trap_param + geometry_param + ")");
  w.open("{");
  w.line(fmt::format("*albedo = {};  // material 0 '{}'", lit.vec3(mats[0].color), kernel_text(mats[0].name)));
  w.line(fmt::format("*specular = {};", lit.typed(mats[0].specular)));
  w.line(fmt::format("*shininess = {};", lit.typed(mats[0].shininess)));
  if (mats.size() == 1) w.line("(void)id;");
  for (size_t i = 1; i < mats.size(); ++i) {
    const auto& md = mats[i];
    w.line(fmt::format("// material {} '{}' ({})", i, kernel_text(md.name), where(md.loc)));
    w.line(fmt::format("mask is{} = id == {};", i, lit.real(double(i))));
    w.line(fmt::format("*albedo = v3_select(*albedo, {}, is{});", lit.vec3(md.color), i));
    w.line(fmt::format("*specular = SEL(*specular, {}, is{});", lit.typed(md.specular), i));
    w.line(fmt::format("*shininess = SEL(*shininess, {}, is{});", lit.typed(md.shininess), i));
    if (!md.trap_palette.empty()) emit_trap_palette(w, lit, md, i);  // palette_emitter.cpp
    if (!md.coloring.empty()) emit_coloring(w, lit, md, i);
  }
  w.close("}");
  w.blank();

  if (plan.effects.reflections.depth > 0 && !blended) {  // blended: the record carries it
    w.line("// ---- reflectivity per material (Fresnel-Schlick R0) ----");
    w.line("real material_reflectivity(real id)");
    w.open("{");
    w.line(fmt::format("real r = {};", lit.typed(mats[0].reflectivity)));
    if (mats.size() == 1) w.line("(void)id;");
    for (size_t i = 1; i < mats.size(); ++i)
      w.line(fmt::format("r = SEL(r, {}, id == {});  // '{}'", lit.typed(mats[i].reflectivity), lit.real(double(i)),
                         kernel_text(mats[i].name)));
    w.line("return r;");
    w.close("}");
    w.blank();
  }
  return w.take();
}

std::string emit_shading(const ir::RenderPlan& plan, const ir::Analyses& facts, const Literals& lit,
                         std::set<std::string>& used) {
  const bool blended = facts.material_blend;
  const ir::RayBounds* bounds = facts.ray_bounds ? &*facts.ray_bounds : nullptr;
  const ir::ShadowBounds* open = facts.shadow_bounds ? &*facts.shadow_bounds : nullptr;
  const bool traps = facts.orbit_traps;  // any orbit-trap material: the trap value comes along
  std::string trap_param = traps ? ", real trap" : "";
  CodeWriter w;
  const bool ao = plan.effects.ambient_occlusion.enabled;
  bool any_shadows = false;
  for (const auto& l : plan.lights) any_shadows |= l.shadows != ir::Light::Shadows::None;
  w.line("// ---- lighting: v points from the surface to the eye ----");
  std::string mat_params = blended ? "vec3 albedo, real specular, real shininess" : "real mat" + trap_param;
  w.line(fmt::format("vec3 shade_surface(TIME_PARAM vec3 p, vec3 n, vec3 v, {}{}{})", mat_params, ao ? ", real occlusion" : "",
                     any_shadows ? ", real footprint, mask hit" : ""));
  w.open("{");
  if (!blended) {
    w.line("vec3 albedo;");
    w.line("real specular, shininess;");
    w.line(std::string("material_of(mat, &albedo, &specular, &shininess") + (traps ? ", trap" : "") +
           (facts.coloring_geometry ? ", p, n" : "") + ");");
  }
  ir::Vec3d ambient{0, 0, 0};
  for (const auto& l : plan.lights)
    if (l.kind == ir::LightKind::Ambient)
      for (int i = 0; i < 3; ++i) ambient[i] += l.color[i] * l.intensity;
  w.line(fmt::format("vec3 c = v3_mul(albedo, {});  // ambient, all ambient lights summed", lit.vec3(ambient)));
  if (ao) w.line("c = v3_scale(c, occlusion);  // ambient occlusion dims the ambient light only");
  if (any_shadows) {
    // Shadow rays leave from two footprints above the surface and take steps
    // of at least half a footprint, so they neither self-shadow nor stall.
    w.line("const vec3 shadow_origin = v3_mad(p, n, 2.0f * footprint);");
  }
  bool any_direct = false;
  for (size_t i = 0; i < plan.lights.size(); ++i) {
    const ir::Light& l = plan.lights[i];
    ir::Vec3d radiance{l.color[0] * l.intensity, l.color[1] * l.intensity, l.color[2] * l.intensity};
    // An animated intensity scales the colour per frame.
    std::string rad = l.intensity_anim ? fmt::format("v3_scale({}, {})", lit.vec3(l.color), animated(l.intensity_anim, l.intensity, lit))
                                       : lit.vec3(radiance);
    if (l.kind == ir::LightKind::Directional) {
      any_direct = true;
      w.line(fmt::format("// light {}: directional ({})", i, where(l.loc)));
      const ir::Vec3d dir{-l.direction[0], -l.direction[1], -l.direction[2]};
      std::string to_light = lit.vec3(dir);
      std::string term = fmt::format("shade_blinn_phong(n, {}, v, albedo, specular, shininess, {})", to_light, rad);
      std::string sh = shadow_call(l, to_light, lit.real(plan.march.max_distance), lit, bounds, used, open, &dir);
      if (!sh.empty()) term = fmt::format("v3_scale({}, {})", term, sh);
      w.line(fmt::format("c = v3_add(c, {});", term));
    } else if (l.kind == ir::LightKind::Point) {
      any_direct = true;
      w.line(fmt::format("// light {}: point, falls off with the squared distance ({})", i, where(l.loc)));
      w.open("{");
      w.line(fmt::format("vec3 l = v3_sub({}, p);", light_position(l, lit)));
      w.line("real dist2 = fmax(v3_dot(l, l), K(1e-8f));");
      w.line("l = v3_scale(l, rsqrt(dist2));");
      std::string sh = shadow_call(l, "l", "sqrt(dist2)", lit, bounds, used, open, nullptr);
      w.line(fmt::format("c = v3_add(c, v3_scale(shade_blinn_phong(n, l, v, albedo, specular, shininess, {}), {}1.0f / dist2));",
                         rad, sh.empty() ? "" : sh + " * "));
      w.close("}");
    }
  }
  if (any_direct) used.insert("shade_blinn_phong");
  else w.line("(void)p; (void)n; (void)v;");
  w.line("return c;");
  w.close("}");
  return emit_material_table(plan, facts, lit) + w.take();
}

}  // namespace sdfc::codegen::detail
