// Assembles the kernel: header comment, prelude for the width and precision,
// the stdlib functions the scene reaches (and nothing else), the scene and
// shading functions, then the entry points.
#include "sdfc/codegen/emit_opencl.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "code_writer.hpp"
#include "prelude.hpp"
#include "gradient_emitter.hpp"
#include "kernel_text.hpp"
#include "scene_emitter.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/codegen/stdlib_manifest.hpp"
#include "sdfc/ir/printer.hpp"
#include "shading_emitter.hpp"
#include "trap_range.hpp"
#include "trap_shape_emitter.hpp"

namespace sdfc::codegen {

namespace {

using detail::CodeWriter;
using detail::Literals;

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
  w.line(fmt::format("vec3 sdfc_segment(TIME_PARAM vec3 ro, vec3 rd, mask active, real pixel_angle, real jitter,{}",
                     fx.glow.enabled ? " real glow_weight," : ""));
  const bool refl_out = blended && fx.reflections.depth > 0;
  w.line(fmt::format("                  real* t_out, mask* hit_out, vec3* n_out, real* mat_out, real* steps_out{})",
                     refl_out ? ", real* refl_out" : ""));
  w.open("{");
  if (const auto& bounds = m.analyses.ray_bounds) {
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
  } else {
    used.insert("march_sphere_trace");
    w.line(fmt::format("mask hit = march_sphere_trace(TIME_ARG ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps);",
                       lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  }
  used.insert("shade_background");
  w.line(fmt::format("vec3 color = shade_background(rd, {}, {}, {});", lit.vec3(m.plan.camera.up),
                     lit.vec3(m.plan.background.top), lit.vec3(m.plan.background.bottom)));
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
  if (s.normals == ir::NormalMethod::Dual) {
    w.line("n = scene_normal_dual(pos);  // exact gradient by forward-mode differentiation");
  } else {
    const char* normal_fn = s.normals == ir::NormalMethod::Central ? "normal_central" : "normal_tetrahedral";
    used.insert(normal_fn);
    w.line(fmt::format("n = {}(TIME_ARG pos, h);", normal_fn));
  }
  std::string extra;
  if (blended) {
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
      w.line(fmt::format("real occlusion = ao_normal_samples(TIME_ARG pos, n, {}, {}, {});", ao.samples, lit.real(ao.distance),
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
  w.line(fmt::format("*t_out = t; *hit_out = hit; *n_out = n; *mat_out = mat; *steps_out = steps;{}",
                     refl_out ? " *refl_out = refl;" : ""));
  w.line("return color;");
  w.close("}");
  return w.take();
}

// The colour seen along one camera ray: the primary segment and, with
// effects.reflections, a bounded loop of mirror bounces weighted by
// Fresnel-Schlick (no recursion in OpenCL C).
std::string radiance_function(const ir::Module& m, std::set<std::string>& used) {
  const bool blended = m.analyses.material_blend;
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
  w.line(fmt::format("vec3 color = sdfc_segment(TIME_ARG ro, rd, M_TRUE, pixel_angle, jitter,{} &t, &hit, normal, mat, steps{});",
                     glow ? " 1.0f," : "", refl_arg));
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
    w.line(fmt::format("seg = sdfc_segment(TIME_ARG ro, rd, alive, pixel_angle, (real)(0.0f),{} &t, &hit, &n, &id, &s{});",
                       glow ? " 0.0f," : "", refl_arg));
    w.line("alive = alive & hit;");
    w.close("}");
    w.line("color = v3_add(sum, v3_mul(weight, seg));  // the last segment counts in full");
  }
  w.line("return color;");
  w.close("}");
  return w.take();
}

std::string render_kernel(const ir::Module& m, const Literals& lit, std::set<std::string>& used, const EmitOptions& opt) {
  const bool aovs = opt.aovs;
  const ir::MarchSettings& s = m.plan.march;
  const ir::Camera& cam = m.plan.camera;
  const bool sampled = s.samples > 1 || cam.aperture > 0;
  CodeWriter w;
  w.line("// ---- the render kernel: a packet of SDFC_PACKET_W x SDFC_PACKET_H pixels per work-item ----");
  w.line("__kernel void sdfc_render(__global float* out, __global const float* frame,");
  w.line("                          const int img_w, const int img_h, const int tile_x0, const int tile_y0,");
  w.line("                          const int tile_w, const int tile_h, const int out_stride)");
  w.open("{");
  w.line("const int gx = get_global_id(0), gy = get_global_id(1);");
  w.line("const int x0 = gx * SDFC_PACKET_W, y0 = gy * SDFC_PACKET_H;");
  w.line("(void)tile_w;");
  w.line("real px0 = (real)((scalar)(tile_x0 + x0)) + LANE_X;  // left edges of the lanes' pixels");
  w.line("real py0 = (real)((scalar)(tile_y0 + y0)) + LANE_Y;  // top edges");
  w.line("// camera basis from the frame block (float high + low parts, see frame_params.cpp)");
  w.line(fmt::format("#define FRAME3(i) v3((real)((scalar)frame[i] + (scalar)frame[i + {}]), (real)((scalar)frame[i + 1] + "
                     "(scalar)frame[i + {}]), (real)((scalar)frame[i + 2] + (scalar)frame[i + {}]))",
                     abi::kLowPart, abi::kLowPart + 1, abi::kLowPart + 2));
  w.line(fmt::format("vec3 eye = FRAME3({}), forward = FRAME3({}), right = FRAME3({}), up = FRAME3({});", abi::kEye,
                     abi::kForward, abi::kRight, abi::kUp));
  w.line("#undef FRAME3");
  w.line(fmt::format("const scalar pixel_angle = (scalar)frame[{}];", abi::kPixelAngle));
  if (m.analyses.uses_time) w.line(fmt::format("const scalar time = (scalar)frame[{}];  // the scene is animated", abi::kTime));
  w.line(aovs ? "real depth, mat, steps, iterations;" : "real depth, mat, steps;");
  w.line("vec3 normal;");
  std::string post;  // per-sample exposure and tone curve
  if (s.exposure != 0) post += fmt::format("c = v3_scale(c, {});  // render.exposure: {} stop(s)\n", lit.real(std::exp2(s.exposure)), s.exposure);
  if (opt.linear) {
    // EmitOptions::linear: the colour leaves before the tone curve and gamma
  } else if (s.tone_mapping == ir::MarchSettings::ToneMapping::Reinhard) {
    used.insert("tonemap_reinhard");
    post += "c = tonemap_reinhard(c);\n";
  } else if (s.tone_mapping == ir::MarchSettings::ToneMapping::Aces) {
    used.insert("tonemap_aces");
    post += "c = tonemap_aces(c);\n";
  }
  if (sampled && !opt.linear && s.tone_mapping == ir::MarchSettings::ToneMapping::Clamp) {
    // Clamping is the tone curve: per sample, so the mean of any subset of
    // samples (a progressive pass) averages like the mean of all of them.
    post += "c = v3(clamp(c.x, K(0.0f), K(1.0f)), clamp(c.y, K(0.0f), K(1.0f)), clamp(c.z, K(0.0f), K(1.0f)));\n";
  }
  auto emit_post = [&] {
    size_t at = 0;
    while (at < post.size()) {
      size_t nl = post.find('\n', at);
      w.line(post.substr(at, nl - at));
      at = nl + 1;
    }
    // EmitOptions::alpha: a camera ray that misses adds no colour (premultiplied by coverage)
    if (opt.alpha) w.line(fmt::format("c = v3_select(v3_splat(0.0f), c, {} >= 0.0f);", sampled ? "d_s" : "depth"));
  };
  if (!sampled) {
    w.line("real px = px0 + 0.5f, py = py0 + 0.5f;  // pixel centres");
    w.line("real u = 2.0f * px / (real)((scalar)img_w) - 1.0f;");
    w.line("real v = 1.0f - 2.0f * py / (real)((scalar)img_h);");
    w.line("vec3 rd = v3_normalize(v3_add(forward, v3_add(v3_scale(right, u), v3_scale(up, v))));");
    if (s.dither) {
      used.insert("fx_hash");
      w.line("real jitter = fx_hash(px, py, (real)(7.0f));");
    } else {
      w.line("real jitter = 0.0f;");
    }
    w.line("vec3 c = sdfc_radiance(TIME_ARG eye, rd, pixel_angle, jitter, &depth, &normal, &mat, &steps);");
    if (aovs) {
      w.line("iterations = SEL((real)(0.0f), scene_iterations(TIME_ARG v3_mad(eye, rd, fmax(depth, K(0.0f)))), depth >= 0.0f);");
      w.line("real coverage = SEL((real)(0.0f), (real)(1.0f), depth >= 0.0f);");
    }
    emit_post();
    w.line("vec3 color = c;");
  } else {
    used.insert("fx_hash");
    used.insert("fx_fract");
    w.line(fmt::format("// render.samples: samples [frame[{0}], frame[{0}] + frame[{1}]) of this pixel, placed by the",
                       abi::kFirstSample, abi::kSampleCount));
    w.line("// R2 low-discrepancy sequence shifted per pixel (Cranley-Patterson rotation)");
    w.line(fmt::format("const int s_first = (int)frame[{}], s_count = max((int)frame[{}], 1);", abi::kFirstSample,
                       abi::kSampleCount));
    w.line("real rx = fx_hash(px0, py0, (real)(1.0f)), ry = fx_hash(px0, py0, (real)(2.0f));");
    if (cam.aperture > 0) {
      w.line(fmt::format("// camera.aperture: a thin lens focused at frame[{}], sampled over its disc", abi::kFocus));
      w.line("real lx = fx_hash(px0, py0, (real)(3.0f)), ly = fx_hash(px0, py0, (real)(4.0f));");
      w.line(fmt::format("const scalar focus = (scalar)frame[{}];", abi::kFocus));
      w.line("vec3 lens_right = v3_normalize(right), lens_up = v3_normalize(up);");
    }
    w.line("vec3 color = v3_splat(0.0f);");
    w.line("// the AOVs are pixel averages over the pass's samples: hit = coverage (the fraction that");
    w.line("// hits); depth, normal (normalised) and iterations = means over the samples that hit;");
    w.line("// steps = mean over all; material = that of the first sample (in sample order) that hits");
    w.line("real hits = 0.0f, depth_sum = 0.0f, steps_sum = 0.0f;");
    w.line("vec3 normal_sum = v3_splat(0.0f);");
    w.line("mat = (real)(-1.0f);");
    if (aovs) w.line("real iter_sum = 0.0f;");
    w.line("for (int si = s_first; si < s_first + s_count; ++si)");
    w.open("{");
    w.line("const scalar sf = (scalar)si;");
    if (s.sampling == ir::MarchSettings::Sampling::Grid) {
      const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(double(s.samples)))));
      w.line(fmt::format("// render.sampling: grid: sample si is the centre of cell (si % {0}, si / {0}) of a {0}x{0} grid", n));
      w.line(fmt::format("real jx = (real)(((scalar)(si % {0}) + K(0.5f)) * K({1})), jy = (real)(((scalar)(si / {0}) + K(0.5f)) * K({1}));",
                         n, lit.real(1.0 / n)));
      w.line("(void)rx; (void)ry;");
    } else {
      w.line("real jx = fx_fract(rx + sf * 0.7548776662f), jy = fx_fract(ry + sf * 0.5698402910f);");
    }
    if (s.filter == ir::MarchSettings::Filter::Tent) {
      used.insert("fx_tent");
      w.line("real px = px0 + 0.5f + fx_tent(jx), py = py0 + 0.5f + fx_tent(jy);  // tent filter, two pixels wide");
    } else {
      w.line("real px = px0 + jx, py = py0 + jy;  // box filter: anywhere in the pixel");
    }
    w.line("real u = 2.0f * px / (real)((scalar)img_w) - 1.0f;");
    w.line("real v = 1.0f - 2.0f * py / (real)((scalar)img_h);");
    w.line("vec3 rd = v3_normalize(v3_add(forward, v3_add(v3_scale(right, u), v3_scale(up, v))));");
    w.line("vec3 ro = eye;");
    if (cam.aperture > 0) {
      w.line("real a = fx_fract(lx + sf * 0.5698402910f), b = fx_fract(ly + sf * 0.7548776662f);");
      w.line(fmt::format("real r = {} * sqrt(a), phi = 6.2831853f * b;", lit.real(0.5 * cam.aperture)));
      w.line("vec3 focal = v3_mad(eye, rd, focus / v3_dot(rd, forward));");
      w.line("ro = v3_add(eye, v3_add(v3_scale(lens_right, r * cos(phi)), v3_scale(lens_up, r * sin(phi))));");
      w.line("rd = v3_normalize(v3_sub(focal, ro));");
    }
    if (s.dither) {
      w.line("real jitter = fx_hash(px, py, (real)(7.0f) + sf);");
    } else {
      w.line("real jitter = 0.0f;");
    }
    w.line("real d_s, mat_s, steps_s;");
    w.line("vec3 n_s;");
    w.line("vec3 c = sdfc_radiance(TIME_ARG ro, rd, pixel_angle, jitter, &d_s, &n_s, &mat_s, &steps_s);");
    emit_post();
    w.line("color = v3_add(color, c);");
    w.line("mask hit_s = d_s >= 0.0f;");
    w.line("mat = SEL(mat, mat_s, hit_s & (hits == 0.0f));  // the first sample that hits");
    w.line("hits += SEL((real)(0.0f), (real)(1.0f), hit_s);");
    w.line("depth_sum += SEL((real)(0.0f), d_s, hit_s);");
    w.line("normal_sum = v3_add(normal_sum, v3_select(v3_splat(0.0f), n_s, hit_s));");
    w.line("steps_sum += steps_s;");
    if (aovs)
      w.line("iter_sum += SEL((real)(0.0f), scene_iterations(TIME_ARG v3_mad(ro, rd, fmax(d_s, K(0.0f)))), hit_s);");
    w.close("}");
    w.line("real per_hit = 1.0f / fmax(hits, K(1.0f));");
    w.line("depth = SEL((real)(-1.0f), depth_sum * per_hit, hits > 0.0f);  // -1 marks a pixel no sample hits");
    w.line("real n_len = sqrt(v3_dot(normal_sum, normal_sum));");
    w.line("normal = v3_scale(normal_sum, SEL((real)(0.0f), 1.0f / fmax(n_len, K(1e-30f)), n_len > K(1e-30f)));");
    w.line("steps = steps_sum * (1.0f / (scalar)s_count);");
    if (aovs) {
      w.line("iterations = iter_sum * per_hit;");
      w.line("real coverage = hits * (1.0f / (scalar)s_count);");
    }
    w.line("color = v3_scale(color, 1.0f / (scalar)s_count);");
  }
  if (!opt.linear) {
    used.insert("shade_encode");
    w.line(fmt::format("color = shade_encode(color, {});", lit.real(1.0 / s.gamma)));
  }
  w.blank();
  w.line("__global float* o = out + y0 * out_stride + x0;");
  w.line("const int plane = out_stride * tile_h;");
  // Each value goes to its plane of the ABI (kernel_abi.hpp), by name.
  auto store = [&](std::string_view plane, const std::string& value, const char* note = "") {
    int k = abi::plane_index(plane);
    std::string at = k == 0 ? "o" : k == 1 ? "o + plane" : fmt::format("o + {} * plane", k);
    w.line(fmt::format("STORE_PACKET({}, {}, out_stride);{}", value, at, note));
  };
  store("r", "color.x");
  store("g", "color.y");
  store("b", "color.z");
  store("depth", "depth");
  if (aovs) {
    w.line("// AOVs: normal (0 on a miss), march steps, material id (-1 on a miss), fractal iterations (0 off");
    w.line("// fractals), hit coverage");
    store("normal_x", "normal.x");
    store("normal_y", "normal.y");
    store("normal_z", "normal.z");
    store("steps", "steps");
    store("material", "mat");
    store("iterations", "iterations");
    store("hit", "coverage", "  // hit: the fraction of samples that hit");
  } else {
    w.line("(void)normal; (void)mat; (void)steps;");
  }
  w.close("}");
  return w.take();
}

// The blended material at given points (tests): albedo r, g, b, specular,
// shininess, reflectivity, each in its own plane of n floats.
std::string probe_material_kernel(bool animated, bool normal) {
  return std::string(R"(// ---- probe: the blended material at given points (tests and tools) ----
__kernel void sdfc_probe_material(__global const float* px, __global const float* py, __global const float* pz,
                                  __global float* out, const int n, const float probe_time)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
)") + (animated ? "    const scalar time = (scalar)probe_time;\n" : "    (void)probe_time;\n") + R"(    mat_record r;
)" + (normal ? "    (void)scene_material(TIME_ARG p, normal_central(TIME_ARG p, K(1e-4f)), &r);\n" : "    (void)scene_material(TIME_ARG p, &r);\n") + R"(    STORE_REAL(r.albedo.x, out + i);
    STORE_REAL(r.albedo.y, out + n + i);
    STORE_REAL(r.albedo.z, out + 2 * n + i);
    STORE_REAL(r.specular, out + 3 * n + i);
    STORE_REAL(r.shininess, out + 4 * n + i);
    STORE_REAL(r.reflectivity, out + 5 * n + i);
}
)";
}

std::string probe_kernel(bool animated) {
  return std::string(R"(// ---- probe: the scene distance at given points and time (tests and tools) ----
__kernel void sdfc_probe(__global const float* px, __global const float* py, __global const float* pz,
                         __global float* out_d, __global float* out_d_mat, __global float* out_mat,
                         const float probe_time)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
)") + (animated ? "    const scalar time = (scalar)probe_time;\n" : "    (void)probe_time;\n") + R"(    real mat;
    STORE_REAL(scene_dist(TIME_ARG p), out_d + i);
    STORE_REAL(scene_dist_mat(TIME_ARG p, &mat), out_d_mat + i);
    STORE_REAL(mat, out_mat + i);
}
)";
}

}  // namespace

EmittedKernel emit_opencl(const ir::Module& m, const EmitOptions& opt) {
  int wd = opt.simd_width;
  if (wd != 1 && wd != 2 && wd != 4 && wd != 8 && wd != 16)
    throw std::invalid_argument(fmt::format("SIMD width must be 1, 2, 4, 8 or 16, not {}", wd));
  const int rows = opt.packet_rows > 0 ? opt.packet_rows : (wd == 16 ? 4 : 1);
  if (wd % rows != 0 || (rows & (rows - 1)) != 0)
    throw std::invalid_argument(fmt::format("packet rows must be a power of two dividing the SIMD width {}, not {}", wd, rows));
  if (m.root == ir::kNoNode || !m.graph->node(m.root).props.known)
    throw std::logic_error("emit_opencl needs a module after infer_properties");
  if (!m.analyses.known) throw std::logic_error("emit_opencl needs a module after the analyse pass");
  const ir::Analyses& facts = m.analyses;
  Literals lit(m.plan.march.precision);
  std::set<std::string> used;
  std::string scene = detail::emit_scene_functions(m, lit, used);
  if (opt.aovs) scene += "\n" + detail::emit_scene_iterations(m, lit, used);
  if (m.plan.march.normals == ir::NormalMethod::Dual) scene += "\n" + detail::emit_scene_gradient(m, lit, used);
  // orbit_trap.range: auto is measured here, on the fractals' surfaces (trap_range.cpp)
  std::string shading = detail::emit_shading(detail::with_trap_ranges(m), facts, lit, used);
  if (facts.material_blend) shading += "\n" + detail::emit_scene_material(m, lit, used);
  std::string kernel = segment_function(m, lit, used) + "\n" + radiance_function(m, used) + "\n" +
                       render_kernel(m, lit, used, opt);
  if (opt.probe_kernel) kernel += "\n" + probe_kernel(facts.uses_time);
  if (opt.probe_kernel && facts.material_blend) kernel += "\n" + probe_material_kernel(facts.uses_time, facts.coloring_geometry);

  // a normal for the mesh colour and the material probe, which have none of their own
  if (facts.coloring_geometry) used.insert("normal_central");
  std::string trap_shapes = detail::emit_trap_shapes(m.plan, lit, used);  // orbit_trap.shape (trap_shape_emitter.cpp)
  auto fns = StdlibManifest::instance().closure({used.begin(), used.end()});
  EmittedKernel k;
  k.simd_width = wd;
  k.packet_rows = rows;
  k.planes.assign(abi::kImagePlanes.begin(), abi::kImagePlanes.end());
  if (opt.aovs) k.planes.insert(k.planes.end(), abi::kAovPlanes.begin(), abi::kAovPlanes.end());
  k.frame_floats = abi::kFrameFloats;
  std::string before, after;
  for (const auto* f : fns) {
    k.stdlib_functions.push_back(f->name);
    (f->after_scene ? after : before) += "\n" + f->text;
  }

  std::string& src = k.source;
  src += fmt::format("// Generated by sdfc from {}. Do not edit: edit the scene.\n", kernel_text(m.source_name, 256));
  src += fmt::format("// precision: {}, SIMD width: {} ({}x{} pixels), IR nodes: {}\n",
                     m.plan.march.precision == ir::Precision::Float ? "float" : "double", wd, wd / rows, rows,
                     ir::count_nodes(m));
  src += "// stdlib functions:";
  for (const auto& n : k.stdlib_functions) src += " " + n;
  src += "\n\n" + detail::prelude(wd, rows, m.plan.march.precision, facts.uses_time);
  src += "\n// ---- stdlib ----" + before + trap_shapes + "\n";
  src += scene + "\n";
  if (!after.empty()) src += "// ---- stdlib that calls the scene ----" + after + "\n";
  src += shading + "\n" + kernel;
  if (!kernel_source_is_plain(src)) throw std::logic_error("generated kernel holds a control or non-ASCII byte");
  return k;
}

}  // namespace sdfc::codegen
