// Assembles the kernel: header comment, prelude for the width and precision,
// the stdlib functions the scene reaches (and nothing else), the scene and
// shading functions, then the entry points.
#include "sdfc/codegen/emit_opencl.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "code_writer.hpp"
#include "prelude.hpp"
#include "gradient_emitter.hpp"
#include "scene_emitter.hpp"
#include "sdfc/codegen/stdlib_manifest.hpp"
#include "sdfc/ir/printer.hpp"
#include "shading_emitter.hpp"

namespace sdfc::codegen {

namespace {

using detail::CodeWriter;
using detail::Literals;

std::string render_kernel(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  const ir::MarchSettings& s = m.plan.march;
  const ir::Props& root = m.graph->node(m.root).props;
  CodeWriter w;
  w.line("// ---- the render kernel: SDFC_WIDTH adjacent pixels per work-item ----");
  w.line("__kernel void sdfc_render(__global float* out, __global const float* frame,");
  w.line("                          const int img_w, const int img_h, const int tile_x0, const int tile_y0,");
  w.line("                          const int tile_w, const int tile_h, const int out_stride)");
  w.open("{");
  w.line("const int gx = get_global_id(0), gy = get_global_id(1);");
  w.line("const int x0 = gx * SDFC_WIDTH;");
  w.line("(void)tile_w;");
  w.line("real px = (real)((scalar)(tile_x0 + x0)) + LANE_IDS + 0.5f;  // pixel centres of the lanes");
  w.line("real py = (real)((scalar)(tile_y0 + gy) + 0.5f);");
  w.line("// camera basis from the frame block (float high + low parts, see frame_params.cpp)");
  w.line("#define FRAME3(i) v3((real)((scalar)frame[i] + (scalar)frame[i + 3]), (real)((scalar)frame[i + 1] + (scalar)frame[i + 4]), (real)((scalar)frame[i + 2] + (scalar)frame[i + 5]))");
  w.line("vec3 ro = FRAME3(0), forward = FRAME3(6), right = FRAME3(12), up = FRAME3(18);");
  w.line("#undef FRAME3");
  w.line("const scalar pixel_angle = (scalar)frame[24];");
  w.line("real u = 2.0f * px / (real)((scalar)img_w) - 1.0f;");
  w.line("real v = 1.0f - 2.0f * py / (real)((scalar)img_h);");
  w.line("vec3 rd = v3_normalize(v3_add(forward, v3_add(v3_scale(right, u), v3_scale(up, v))));");
  w.blank();
  if (root.bounds.finite()) {
    // Pad by 1% of the size plus a little: the hit test accepts points up to
    // an epsilon outside the surface.
    double ext = 0;
    for (int i = 0; i < 3; ++i) ext = std::max(ext, root.bounds.hi[i] - root.bounds.lo[i]);
    ir::Box3 b = root.bounds.padded(0.01 * ext + 1e-3);
    used.insert("ray_box");
    w.line("// march only where the ray crosses the scene's bounds (inferred from the IR)");
    w.line("real t0, t1;");
    w.line(fmt::format("mask active = ray_box(ro, rd, {}, {}, &t0, &t1);", lit.vec3(b.lo), lit.vec3(b.hi)));
    w.line(fmt::format("t1 = fmin(t1, {});", lit.real(s.max_distance)));
  } else {
    w.line("// the scene is unbounded (it holds a plane): march the whole range");
    w.line("real t0 = 0.0f;");
    w.line(fmt::format("real t1 = {};", lit.typed(s.max_distance)));
    w.line("mask active = M_TRUE;");
  }
  used.insert("march_sphere_trace");
  w.line("real t, steps;");
  w.line(fmt::format("mask hit = march_sphere_trace(ro, rd, t0, t1, active, pixel_angle, {}, {}, {}, &t, &steps);",
                     lit.real(s.hit_epsilon), lit.real(s.step_factor), s.max_steps));
  w.line("(void)steps;");
  w.blank();
  used.insert("shade_background");
  used.insert("shade_encode");
  w.line(fmt::format("vec3 color = shade_background(rd, {}, {}, {});", lit.vec3(m.plan.camera.up),
                     lit.vec3(m.plan.background.top), lit.vec3(m.plan.background.bottom)));
  w.line("if (M_ANY(hit))");
  w.open("{");
  w.line("// shading runs once per packet with a hit, never inside the march");
  w.line("vec3 pos = v3_mad(ro, rd, t);");
  w.line("real h = fmax(pixel_angle * t * 0.5f, K(1e-6f));  // finite-difference step: half a pixel footprint");
  if (s.normals == ir::NormalMethod::Dual) {
    w.line("vec3 n = scene_normal_dual(pos);  // exact gradient by forward-mode differentiation");
    w.line("(void)h;");
  } else {
    const char* normal_fn = s.normals == ir::NormalMethod::Central ? "normal_central" : "normal_tetrahedral";
    used.insert(normal_fn);
    w.line(fmt::format("vec3 n = {}(pos, h);", normal_fn));
  }
  w.line("real mat;");
  w.line("(void)scene_dist_mat(pos, &mat);");
  bool traps = false;
  for (const auto& md : m.plan.materials) traps = traps || !md.trap_palette.empty();
  if (traps) w.line("real trap = scene_trap(pos);  // orbit-trap colour, once per hit");
  w.line(std::string("vec3 lit = shade_surface(pos, n, v3_scale(rd, -1.0f), mat") + (traps ? ", trap" : "") + ");");
  w.line("color = v3_select(color, lit, hit);");
  w.close("}");
  w.line(fmt::format("color = shade_encode(color, {});", lit.real(1.0 / s.gamma)));
  w.line("real depth = SEL((real)(-1.0f), t, hit);  // -1 marks a miss");
  w.blank();
  w.line("__global float* o = out + gy * out_stride + x0;");
  w.line("const int plane = out_stride * tile_h;");
  w.line("STORE_REAL(color.x, o);");
  w.line("STORE_REAL(color.y, o + plane);");
  w.line("STORE_REAL(color.z, o + 2 * plane);");
  w.line("STORE_REAL(depth, o + 3 * plane);");
  w.close("}");
  return w.take();
}

std::string probe_kernel() {
  return R"(// ---- probe: the scene distance at given points (tests and tools) ----
__kernel void sdfc_probe(__global const float* px, __global const float* py, __global const float* pz,
                         __global float* out_d, __global float* out_d_mat, __global float* out_mat)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
    real mat;
    STORE_REAL(scene_dist(p), out_d + i);
    STORE_REAL(scene_dist_mat(p, &mat), out_d_mat + i);
    STORE_REAL(mat, out_mat + i);
}
)";
}

}  // namespace

EmittedKernel emit_opencl(const ir::Module& m, const EmitOptions& opt) {
  int wd = opt.simd_width;
  if (wd != 1 && wd != 2 && wd != 4 && wd != 8 && wd != 16)
    throw std::invalid_argument(fmt::format("SIMD width must be 1, 2, 4, 8 or 16, not {}", wd));
  if (m.root == ir::kNoNode || !m.graph->node(m.root).props.known)
    throw std::logic_error("emit_opencl needs a module after infer_properties");
  Literals lit(m.plan.march.precision);
  std::set<std::string> used;
  std::string scene = detail::emit_scene_functions(m, lit, used);
  if (m.plan.march.normals == ir::NormalMethod::Dual) scene += "\n" + detail::emit_scene_gradient(m, lit, used);
  std::string shading = detail::emit_shading(m.plan, lit, used);
  std::string kernel = render_kernel(m, lit, used);
  if (opt.probe_kernel) kernel += "\n" + probe_kernel();

  auto fns = StdlibManifest::instance().closure({used.begin(), used.end()});
  EmittedKernel k;
  k.simd_width = wd;
  k.planes = {"r", "g", "b", "depth"};
  k.frame_floats = kFrameFloats;
  std::string before, after;
  for (const auto* f : fns) {
    k.stdlib_functions.push_back(f->name);
    (f->after_scene ? after : before) += "\n" + f->text;
  }

  std::string& src = k.source;
  src += fmt::format("// Generated by sdfc from {}. Do not edit: edit the scene.\n", m.source_name);
  src += fmt::format("// precision: {}, SIMD width: {}, IR nodes: {}\n",
                     m.plan.march.precision == ir::Precision::Float ? "float" : "double", wd, ir::count_nodes(m));
  src += "// stdlib functions:";
  for (const auto& n : k.stdlib_functions) src += " " + n;
  src += "\n\n" + detail::prelude(wd, m.plan.march.precision);
  src += "\n// ---- stdlib ----" + before + "\n";
  src += scene + "\n";
  if (!after.empty()) src += "// ---- stdlib that calls the scene ----" + after + "\n";
  src += shading + "\n" + kernel;
  return k;
}

}  // namespace sdfc::codegen
