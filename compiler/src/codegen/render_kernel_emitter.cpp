// The render kernel: places a pixel's samples (R2 sequence or grid, box or
// tent filter, thin-lens depth of field), runs the radiance of each, applies
// exposure and the tone curve per sample, averages, gamma-encodes and stores
// the planes of the ABI.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "entry_emitters.hpp"
#include "object_set_emitter.hpp"
#include "sdfc/codegen/kernel_abi.hpp"

namespace sdfc::codegen::detail {

std::string render_kernel(const ir::Module& m, const Literals& lit, std::set<std::string>& used, const EmitOptions& opt) {
  const bool aovs = opt.aovs;
  const ir::MarchSettings& s = m.plan.march;
  const ir::Camera& cam = m.plan.camera;
  const bool path = m.plan.transport.integrator == ir::Transport::Integrator::Path;
  const bool sampled = s.samples > 1 || cam.aperture > 0 || path;  // a path is sampled even at one sample
  const bool albedo = path && aovs;  // kernel_abi.hpp's kPathAovPlanes
  CodeWriter w;
  w.line("// ---- the render kernel: a packet of SDFC_PACKET_W x SDFC_PACKET_H pixels per work-item ----");
  w.line("__kernel void sdfc_render(__global float* out, __global const float* frame,");
  w.line("                          const int img_w, const int img_h, const int tile_x0, const int tile_y0,");
  // background.map: the map and its sampling tables (path_env_emitter.cpp)
  w.line(env_map_used(m.plan) ? "                          const int tile_w, const int tile_h, const int out_stride, __global const float* envmap)"
                              : "                          const int tile_w, const int tile_h, const int out_stride)");
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
  if (m.analyses.uses_time || m.unlocked > 0)
    w.line(fmt::format("const scalar time = (scalar)frame[{}];  // the scene is animated", abi::kTime));
  if (m.unlocked > 0) w.line(fmt::format("__global const float* unlocked = frame + {};  // the unlocked values", abi::kFrameFloats));
  if (has_object_sets(m))
    w.line(fmt::format("__global const float* scene_data = frame + {};  // the object sets' numbers", abi::kFrameFloats + m.unlocked));
  w.line(aovs ? "real depth, mat, steps, iterations;" : "real depth, mat, steps;");
  w.line("vec3 normal;");
  if (albedo) w.line("vec3 albedo;  // the first hit's, for denoisers");
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
    if (albedo) w.line("vec3 albedo_sum = v3_splat(0.0f), a_s;  // albedo: the mean over the samples that hit");
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
    if (path)  // render.integrator: path, seeded by the absolute pixel and the sample
      w.line(std::string("vec3 c = sdfc_path(TIME_ARG ro, rd, pixel_angle, jitter, px0, py0, sf, &d_s, &n_s, &mat_s, &steps_s") +
             (albedo ? ", &a_s" : "") + (env_map_used(m.plan) ? ", envmap);" : ");"));
    else
      w.line("vec3 c = sdfc_radiance(TIME_ARG ro, rd, pixel_angle, jitter, &d_s, &n_s, &mat_s, &steps_s);");
    emit_post();
    w.line("color = v3_add(color, c);");
    w.line("mask hit_s = d_s >= 0.0f;");
    w.line("mat = SEL(mat, mat_s, hit_s & (hits == 0.0f));  // the first sample that hits");
    w.line("hits += SEL((real)(0.0f), (real)(1.0f), hit_s);");
    w.line("depth_sum += SEL((real)(0.0f), d_s, hit_s);");
    w.line("normal_sum = v3_add(normal_sum, v3_select(v3_splat(0.0f), n_s, hit_s));");
    if (albedo) w.line("albedo_sum = v3_add(albedo_sum, v3_select(v3_splat(0.0f), a_s, hit_s));");
    w.line("steps_sum += steps_s;");
    if (aovs)
      w.line("iter_sum += SEL((real)(0.0f), scene_iterations(TIME_ARG v3_mad(ro, rd, fmax(d_s, K(0.0f)))), hit_s);");
    w.close("}");
    w.line("real per_hit = 1.0f / fmax(hits, K(1.0f));");
    w.line("depth = SEL((real)(-1.0f), depth_sum * per_hit, hits > 0.0f);  // -1 marks a pixel no sample hits");
    w.line("real n_len = sqrt(v3_dot(normal_sum, normal_sum));");
    w.line("normal = v3_scale(normal_sum, SEL((real)(0.0f), 1.0f / fmax(n_len, K(1e-30f)), n_len > K(1e-30f)));");
    w.line("steps = steps_sum * (1.0f / (scalar)s_count);");
    if (albedo) w.line("albedo = v3_scale(albedo_sum, per_hit);");
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
    if (albedo) {
      store("albedo_r", "albedo.x", "  // albedo: the first hit's colour (0 on a miss)");
      store("albedo_g", "albedo.y");
      store("albedo_b", "albedo.z");
    }
  } else if (opt.steps_plane) {
    w.line("(void)normal; (void)mat;");
    w.line(fmt::format("STORE_PACKET(steps, o + {} * plane, out_stride);  // steps, the only AOV plane here",
                       abi::kImagePlanes.size()));
  } else {
    w.line("(void)normal; (void)mat; (void)steps;");
  }
  w.close("}");
  return w.take();
}

}  // namespace sdfc::codegen::detail
