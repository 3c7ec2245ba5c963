// The path integrator (render.integrator: path): sdfc_path_hit
// marches one ray of a path and finds its surface, sdfc_path follows a path
// from the camera: the environment where it leaves the scene, emission where
// it hits, next-event estimation to every light at each vertex (the
// DE-marched shadow rays of the direct integrator), a cosine-weighted
// diffuse or GGX bounce or glass (path_glass_emitter.cpp), Russian
// roulette. Glossy, emission and glass code is emitted only for scenes
// whose materials have them.
#include <fmt/format.h>

#include <set>

#include "entry_emitters.hpp"
#include "kernel_text.hpp"
#include "object_set_emitter.hpp"
#include "shading_emitter.hpp"

namespace sdfc::codegen::detail {

namespace {

// sdfc_path_hit: the march of one path segment from a virtual origin ro
// that lies `from` behind the segment's start, so t counts the path's whole
// length and hit epsilons and normal steps follow the pixel footprint there.
// With glass it takes the side it marches on (-1 inside a solid).
std::string hit_function(const ir::Module& m, const Literals& lit, std::set<std::string>& used, bool glass) {
  const ir::MarchSettings& s = m.plan.march;
  const bool blended = m.analyses.material_blend;
  CodeWriter w;
  w.line("// ---- one segment of a path: march from ro + from * rd, then the surface at the hit ----");
  w.line(std::string("mask sdfc_path_hit(TIME_PARAM vec3 ro, vec3 rd, ") + (glass ? "real side, " : "") +
         "mask active, real pixel_angle, real from, real jitter,");
  w.line("                   real* t_out, vec3* n_out, real* id_out, vec3* albedo_out, real* steps_out, mask* escaped)");
  w.open("{");
  if (bounds_clip(w, m, lit, used)) {
    w.line("t0 = fmax(t0, from);");
    w.line(fmt::format("t1 = fmin(t1, from + {});", lit.real(s.max_distance)));
  } else {
    w.line("real t0 = from;");
    w.line(fmt::format("real t1 = from + {};", lit.real(s.max_distance)));
  }
  if (s.dither) {
    w.line(fmt::format("t0 = t0 + jitter * {} * fmax(scene_dist(TIME_ARG v3_mad(ro, rd, t0)), K(0.0f));", lit.real(s.step_factor)));
  } else {
    w.line("(void)jitter;");
  }
  w.line("active = active & (t0 < t1);");
  w.line("const mask entered = active;");
  w.line("real t, steps;");
  if (glass) {
    used.insert("march_signed");
    w.line(fmt::format("mask hit = march_signed(TIME_ARG ro, rd, side, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  } else if (s.refine == ir::MarchSettings::Refine::Bisection) {
    used.insert("march_sphere_trace_refined");
    w.line("real closest;");
    w.line(fmt::format("mask hit = march_sphere_trace_refined(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps, &closest);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
    w.line("(void)closest;");
  } else {
    used.insert("march_sphere_trace");
    w.line(fmt::format("mask hit = march_sphere_trace(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  }
  w.line("// left the scene (missed its bounds or reached max_distance), rather than ran out of steps");
  w.line("*escaped = !hit & (!entered | (t >= t1));");
  w.line("vec3 n = v3_splat(0.0f), albedo = v3_splat(0.0f);");
  w.line("real id = -1.0f;");
  w.line("if (M_ANY(hit))");
  w.open("{");
  w.line("vec3 pos = v3_mad(ro, rd, t);");
  w.line(fmt::format("real h = fmax(pixel_angle * t * {}, K({}));", lit.real(s.normal_step), lit.real(s.normal_step_floor)));
  const bool below = bounded_shading(m);  // with an object set, as the direct integrator's hits
  if (below) {
    emit_bounded_hit(w, m, lit, used, "os_cone_none()");
  } else if (s.normals == ir::NormalMethod::Dual) {
    w.line("n = scene_normal_dual(pos);");
    w.line("(void)h;");
  } else {
    const char* normal_fn = s.normals == ir::NormalMethod::Central ? "normal_central" : "normal_tetrahedral";
    used.insert(normal_fn);
    w.line(fmt::format("n = {}(TIME_ARG pos, h);", normal_fn));
  }
  w.line("real spec, shin;");
  if (blended) {
    w.line("mat_record look;  // the materials mixed across smooth blends");
    w.line(m.analyses.coloring_geometry ? "id = scene_material(TIME_ARG pos, n, &look);" : "id = scene_material(TIME_ARG pos, &look);");
    w.line("albedo = look.albedo;");
    w.line("(void)spec; (void)shin;");
  } else {
    if (below)
      w.line("(void)d_hit;");
    else if (const auto& uni = m.analyses.uniform_material)
      w.line(fmt::format("id = {};", lit.typed(*uni)));
    else
      w.line("(void)scene_dist_mat(TIME_ARG pos, &id);");
    w.line(std::string("material_of(id, &albedo, &spec, &shin") + (m.analyses.orbit_traps ? ", scene_trap(TIME_ARG pos)" : "") +
           (m.analyses.coloring_geometry ? ", pos, n" : "") + ");");
  }
  w.close("}");
  w.line("*t_out = t; *n_out = n; *id_out = SEL((real)(-1.0f), id, hit); *albedo_out = albedo; *steps_out = steps;");
  w.line("return hit;");
  w.close("}");
  return w.take();
}

// Which lobe a glossy vertex's bounce takes: the GGX lobe with the
// probability ps of its Fresnel reflectance, else the diffuse one.
void lobe_choice(CodeWriter& w) {
  w.line("// pick the GGX lobe with the probability of its Fresnel reflectance, else the diffuse one");
  w.line("real nv = fmax(v3_dot(n, v), K(1e-4f));");
  w.line("vec3 fv = path_fresnel(f0, nv);");
  w.line("real ws = v3_max_comp(fv), wd = v3_max_comp(v3_mul(diffuse, v3_sub(v3_splat(1.0f), fv)));");
  w.line("real ps = SEL((real)(0.0f), clamp(ws / fmax(ws + wd, K(1e-6f)), K(0.05f), K(1.0f)), lobe);");
}

}  // namespace

std::string path_functions(const ir::Module& m, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used,
                           bool aovs) {
  const ir::Transport& tr = plan.transport;
  const bool glossy = any_glossy(plan), emission = any_emission(plan), glass = any_glass(plan);
  const ir::RayBounds* bounds = m.analyses.ray_bounds ? &*m.analyses.ray_bounds : nullptr;
  const bool clamp = tr.clamp > 0;
  const bool envmap = env_map_used(plan);
  used.insert({"path_rand", "path_cosine_dir"});
  if (clamp) used.insert("path_firefly");
  if (glossy) used.insert({"path_glossy_eval", "path_ggx_half"});
  if (glass) used.insert({"glass_fresnel", "glass_absorb"});
  std::string out = detail::emit_material_table(plan, m.analyses, lit);
  if (glossy || emission || glass) out += surface_table(plan, glossy, emission, glass, lit) + "\n";
  out += hit_function(m, lit, used, glass) + "\n";

  CodeWriter w;
  // Light that has scattered `order` times is clamped from the second on (indirect light).
  auto add = [&](const std::string& term, const std::string& lanes, const std::string& order) {
    std::string x = clamp ? fmt::format("({} >= 2 ? path_firefly({}, {}) : {})", order, term, lit.real(tr.clamp), term) : term;
    w.line(fmt::format("sum = v3_add(sum, v3_select(v3_splat(0.0f), {}, {}));", x, lanes));
  };
  w.line("// ---- the path integrator: the light along one camera ray; the AOVs of its first hit ----");
  w.line("vec3 sdfc_path(TIME_PARAM vec3 ro, vec3 rd, real pixel_angle, real jitter, real px, real py, scalar sf,");
  w.line(std::string("               real* depth, vec3* normal, real* mat, real* steps") + (aovs ? ", vec3* albedo_aov" : "") +
         (envmap ? ", __global const float* envmap)" : ")"));
  w.open("{");
  w.line("vec3 sum = v3_splat(0.0f), thr = v3_splat(1.0f);  // the light gathered; the path's throughput");
  w.line("mask alive = M_TRUE;");
  if (aovs) w.line("*albedo_aov = v3_splat(0.0f);  // the first hit's albedo, for denoisers");
  w.line("real from = 0.0f;  // the path's length up to the start of this segment");
  if (envmap) w.line("real pdf_b = 1.0f; mask delta = M_TRUE;  // the last bounce's density; true for camera rays and glass");
  if (glass) {
    w.line("mask inside = !M_TRUE;  // the lanes whose path is inside a glass solid");
    w.line("vec3 sigma_in = v3_splat(0.0f);  // the absorption of the glass they are in");
  }
  w.line(fmt::format("// render.max_bounces: {}; Russian roulette after {} bounces", tr.max_bounces, tr.roulette_after));
  w.line(fmt::format("for (int seg = 0; seg <= {} && M_ANY(alive); ++seg)", tr.max_bounces));
  w.open("{");
  w.line("real t, id, st;");
  w.line("vec3 n, albedo;");
  w.line("mask escaped;");
  w.line(std::string("mask hit = sdfc_path_hit(TIME_ARG ro, rd, ") + (glass ? "SEL((real)(1.0f), (real)(-1.0f), inside), " : "") +
         "alive, pixel_angle, from, jitter, &t, &n, &id, &albedo, &st, &escaped);");
  w.line("hit = hit & alive;");
  if (glass) {
    w.line("// Beer-Lambert along the segment inside glass; a path that does not find its way out is lost");
    w.line("thr = v3_select(thr, v3_mul(thr, glass_absorb(sigma_in, t - from)), inside);");
    w.line("escaped = escaped & !inside;");
  }
  w.line("if (seg == 0)");
  w.open("{");
  w.line("*depth = SEL((real)(-1.0f), t, hit);  // -1 marks a miss");
  w.line("*normal = n; *mat = id; *steps = st;");
  w.line("escaped = !hit;  // a camera ray that runs out of steps shows the background, as in the direct integrator");
  w.close("}");
  w.line("// the environment (the background or sky) where the path leaves the scene; a path that runs out of steps is lost");
  if (envmap)
    env_escape(w, plan, lit, used);
  else
    w.line(fmt::format("vec3 env = {};", background_call(plan, lit, used)));
  add("v3_mul(thr, env)", "alive & escaped", "seg");
  w.line("alive = hit;");
  w.line("if (!M_ANY(alive)) break;");
  w.line("vec3 p = v3_mad(ro, rd, t), v = v3_scale(rd, -1.0f);");
  w.line("// a normal that faces away from the ray (a finite difference across a thin sheet) is turned round");
  w.line("n = v3_select(n, v3_scale(n, -1.0f), v3_dot(n, v) < 0.0f);");
  if (glossy || emission || glass) {
    if (emission) w.line("vec3 emission;");
    if (glossy) w.line("real alpha, metal; mask lobe;");
    if (glass) w.line("mask on_glass; real ior; vec3 sigma;");
    w.line(std::string("path_surface(id") + (emission ? ", &emission" : "") + (glossy ? ", &alpha, &metal, &lobe" : "") +
           (glass ? ", &on_glass, &ior, &sigma" : "") + ");");
  }
  if (glass) {
    w.line("on_glass = on_glass & alive;");
    w.line("alive = alive & (on_glass | !inside);  // inside glass, only a glass surface lets the path out");
  }
  if (aovs)  // denoisers take a perfectly specular surface's albedo as 1
    w.line(glass ? "if (seg == 0) *albedo_aov = v3_select(albedo, v3_splat(1.0f), on_glass);" : "if (seg == 0) *albedo_aov = albedo;");
  if (emission) add("v3_mul(thr, emission)", "alive", "seg");
  w.line(fmt::format("if (seg == {}) break;  // no more scattering", tr.max_bounces));
  if (glossy) {
    w.line("// base colour: diffuse for dielectrics, the reflectance at normal incidence for metals");
    w.line("vec3 f0 = v3_mix(v3_splat(0.04f), albedo, metal);");
    w.line("vec3 diffuse = v3_scale(albedo, 1.0f - metal);");
    w.line("f0 = v3_select(v3_splat(0.0f), f0, lobe);  // materials without roughness or metalness are purely diffuse");
    w.line("diffuse = v3_select(albedo, diffuse, lobe);");
  }
  w.line("const real footprint = fmax(pixel_angle * t, K(1e-5f));");
  w.line("const vec3 shadow_origin = v3_mad(p, n, 2.0f * footprint);");
  w.line("// next-event estimation: every light, through its shadow ray");
  bool any_light = false;
  for (size_t i = 0; i < plan.lights.size(); ++i) {
    const ir::Light& l = plan.lights[i];
    if (l.kind == ir::LightKind::Ambient) continue;  // the environment lights the scene instead
    any_light = true;
    ir::Vec3d radiance{l.color[0] * l.intensity, l.color[1] * l.intensity, l.color[2] * l.intensity};
    std::string rad = l.intensity_anim ? fmt::format("v3_scale({}, {})", lit.vec3(l.color), animated(l.intensity_anim, l.intensity, lit))
                                       : lit.vec3(radiance);
    w.open("{");
    if (l.kind == ir::LightKind::Directional) {
      w.line(fmt::format("// light {}: directional", i));
      w.line(fmt::format("vec3 l = {};", lit.vec3({-l.direction[0], -l.direction[1], -l.direction[2]})));
      w.line(fmt::format("vec3 e = {};", rad));
      w.line(fmt::format("real tmax = {};", lit.typed(plan.march.max_distance)));
    } else {
      w.line(fmt::format("// light {}: point, falls off with the squared distance", i));
      w.line(fmt::format("vec3 l = v3_sub({}, p);", light_position(l, lit)));
      w.line("real dist2 = fmax(v3_dot(l, l), K(1e-8f));");
      w.line("l = v3_scale(l, rsqrt(dist2));");
      w.line(fmt::format("vec3 e = v3_scale({}, 1.0f / dist2);", rad));
      w.line("real tmax = sqrt(dist2);");
    }
    w.line("(void)tmax;");
    std::string f = glossy ? "path_glossy_eval(n, v, l, diffuse, f0, alpha)" : "v3_scale(albedo, fmax(v3_dot(n, l), K(0.0f)))";
    std::string sh = shadow_call(l, "l", "tmax", lit, bounds, used);
    std::string term = fmt::format("v3_mul(thr, v3_mul({}, e))", f);
    if (!sh.empty()) term = fmt::format("v3_scale({}, {})", term, sh);
    add(term, glass ? "hit & !on_glass" : "hit", "seg + 1");  // glass reflects and refracts only in delta directions
    w.close("}");
  }
  if (envmap) {
    if (glossy) lobe_choice(w);  // the map's sample weighs itself against the bounce's density
    env_light(w, plan, lit, used, bounds, glossy, glass ? "hit & !on_glass" : "hit", add);
  } else if (!any_light) {
    w.line("(void)shadow_origin;");
  }
  w.line(fmt::format("const scalar dim = (scalar)(seg * 4);  // four random numbers per bounce"));
  w.line("real u0 = path_rand(px, py, sf, dim), u1 = path_rand(px, py, sf, dim + 1.0f), u2 = path_rand(px, py, sf, dim + 2.0f);");
  if (glass) w.line("const vec3 thr_in = thr;");
  if (glossy) {
    if (!envmap) lobe_choice(w);
    w.line("mask take_spec = u0 < ps;");
    w.line("vec3 h = path_ggx_half(n, alpha, u1, u2);");
    w.line("vec3 ls = v3_normalize(v3_mad(rd, h, -2.0f * v3_dot(rd, h)));  // rd mirrored about h");
    w.line("vec3 ld = path_cosine_dir(n, u1, u2);");
    w.line("real nl = v3_dot(n, ls), vh = fmax(v3_dot(v, h), K(0.0f)), nh = fmax(v3_dot(n, h), K(1e-6f));");
    w.line("// GGX: f cos / pdf = F G vh / (nv nh); diffuse: f cos / pdf = diffuse (1 - F(nv))");
    w.line("vec3 w_spec = v3_scale(path_fresnel(f0, vh), path_ggx_g1(nv, alpha) * path_ggx_g1(fmax(nl, K(0.0f)), alpha) * vh / (nv * nh * fmax(ps, K(1e-6f))));");
    w.line("w_spec = v3_select(w_spec, v3_splat(0.0f), nl <= 0.0f);  // below the surface: the path ends");
    w.line("vec3 w_diff = v3_scale(v3_mul(diffuse, v3_sub(v3_splat(1.0f), fv)), 1.0f / fmax(1.0f - ps, K(1e-6f)));");
    w.line("thr = v3_mul(thr, v3_select(w_diff, w_spec, take_spec));");
    w.line("vec3 nd = v3_select(ld, ls, take_spec);");
    if (envmap) w.line("pdf_b = path_glossy_pdf(n, v, nd, alpha, ps);");
  } else {
    w.line("// a cosine-weighted diffuse bounce: f cos / pdf = albedo");
    if (!glass) w.line("(void)u0;");
    w.line("vec3 nd = path_cosine_dir(n, u1, u2);");
    w.line("thr = v3_mul(thr, albedo);");
    if (envmap) w.line("pdf_b = fmax(v3_dot(n, nd), K(0.0f)) * K(0.31830988618f);");
  }
  if (glass) {
    w.line("vec3 start = shadow_origin;");
    glass_scatter(w);
    if (envmap) w.line("delta = on_glass;");
  }
  w.line(fmt::format("if (seg >= {})", tr.roulette_after));
  w.open("{");
  w.line("// Russian roulette: a path survives with probability q and carries 1 / q more");
  w.line("real q = clamp(v3_max_comp(thr), K(0.05f), K(0.95f));");
  w.line("real u3 = path_rand(px, py, sf, dim + 3.0f);");
  w.line("alive = alive & (u3 < q);");
  w.line("thr = v3_scale(thr, 1.0f / q);");
  w.close("}");
  w.line("alive = alive & (v3_max_comp(thr) > 0.0f);");
  w.line("// the next segment starts two footprints off the surface; its virtual origin lies t behind that");
  w.line("rd = nd;");
  w.line(glass ? "ro = v3_mad(start, rd, -t);" : "ro = v3_mad(shadow_origin, rd, -t);");
  w.line("from = t;");
  w.line("jitter = 0.0f;  // render.dither: the camera ray only");
  if (envmap && !glass) w.line("delta = !M_TRUE;");
  w.close("}");
  w.line("return sum;");
  w.close("}");
  return out + w.take();
}

}  // namespace sdfc::codegen::detail
