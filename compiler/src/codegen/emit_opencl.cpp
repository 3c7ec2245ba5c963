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
#include "entry_emitters.hpp"
#include "prelude.hpp"
#include "gradient_emitter.hpp"
#include "kernel_text.hpp"
#include "object_set_emitter.hpp"
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

int default_packet_rows(int simd_width) {
  switch (simd_width) {
    case 16: return 4;  // 4x4
    case 32: return 4;  // 8x4
    case 64: return 8;  // 8x8
    default: return 1;
  }
}

EmittedKernel emit_opencl(const ir::Module& m, const EmitOptions& opt) {
  int wd = opt.simd_width;
  if (wd < 1 || wd > 64 || (wd & (wd - 1)) != 0)
    throw std::invalid_argument(fmt::format("SIMD width must be 1, 2, 4, 8, 16, 32 or 64, not {}", wd));
  const int rows = opt.packet_rows > 0 ? opt.packet_rows : default_packet_rows(wd);
  if (wd % rows != 0 || (rows & (rows - 1)) != 0)
    throw std::invalid_argument(fmt::format("packet rows must be a power of two dividing the SIMD width {}, not {}", wd, rows));
  if (m.unlocked > 0 && opt.probe_kernel)  // the probes take no frame block to read the values from
    throw std::invalid_argument("a kernel with unlocked values has no probe entries");
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
  // render.integrator: path replaces the direct integrator's shading, segment and radiance (path_emitter.cpp)
  const bool path = m.plan.transport.integrator == ir::Transport::Integrator::Path;
  std::string shading = path ? std::string() : detail::emit_shading(detail::with_trap_ranges(m), facts, lit, used);
  if (facts.material_blend) shading += "\n" + detail::emit_scene_material(m, lit, used);
  std::string kernel = path ? detail::path_functions(m, detail::with_trap_ranges(m), lit, used, opt.aovs) + "\n"
                            : detail::segment_function(m, lit, used) + "\n" + detail::radiance_function(m, lit, used) + "\n";
  kernel += detail::render_kernel(m, lit, used, opt);
  // With object sets the probes take the scene data as their last argument.
  const bool data = detail::has_object_sets(m);
  auto with_data = [&](std::string probe) {
    if (data) probe.replace(probe.find(")\n{"), 2, ", __global const float* scene_data)");
    return probe;
  };
  if (opt.probe_kernel) kernel += "\n" + with_data(probe_kernel(facts.uses_time));
  if (opt.probe_kernel && facts.material_blend)
    kernel += "\n" + with_data(probe_material_kernel(facts.uses_time, facts.coloring_geometry));

  // a normal for the mesh colour and the material probe, which have none of their own
  if (facts.coloring_geometry) used.insert("normal_central");
  std::string trap_shapes = detail::emit_trap_shapes(m.plan, lit, used);  // orbit_trap.shape (trap_shape_emitter.cpp)
  auto fns = StdlibManifest::instance().closure({used.begin(), used.end()});
  EmittedKernel k;
  k.simd_width = wd;
  k.packet_rows = rows;
  k.planes.assign(abi::kImagePlanes.begin(), abi::kImagePlanes.end());
  if (opt.aovs) k.planes.insert(k.planes.end(), abi::kAovPlanes.begin(), abi::kAovPlanes.end());
  else if (opt.steps_plane) k.planes.emplace_back("steps");
  if (opt.aovs && path) k.planes.insert(k.planes.end(), abi::kPathAovPlanes.begin(), abi::kPathAovPlanes.end());
  k.frame_floats = abi::kFrameFloats + m.unlocked;
  k.scene_data = detail::scene_data(m);
  if (detail::env_map_used(m.plan)) k.environment = m.plan.background.map.data;
  std::string before, after;
  for (const auto* f : fns) {
    k.stdlib_functions.push_back(f->name);
    (f->after_scene ? after : before) += "\n" + f->text;
  }

  std::string body = "\n// ---- stdlib ----" + before + trap_shapes + "\n" + scene + "\n";
  if (!after.empty()) body += "// ---- stdlib that calls the scene ----" + after + "\n";
  body += shading + "\n" + kernel + opt.extra_entries;
  std::string& src = k.source;
  src += fmt::format("// Generated by sdfc from {}. Do not edit: edit the scene.\n", kernel_text(m.source_name, 256));
  src += fmt::format("// precision: {}, SIMD width: {} ({}x{} pixels), IR nodes: {}\n",
                     m.plan.march.precision == ir::Precision::Float ? "float" : "double", wd, wd / rows, rows,
                     ir::count_nodes(m));
  src += "// stdlib functions:";
  for (const auto& n : k.stdlib_functions) src += " " + n;
  if (!k.scene_data.empty()) body = detail::scene_data_macros(facts.uses_time, m.unlocked) + body;
  src += "\n\n" + detail::prelude(wd, rows, m.plan.march.precision, facts.uses_time, m.unlocked, body) + body;
  if (!kernel_source_is_plain(src)) throw std::logic_error("generated kernel holds a control or non-ASCII byte");
  return k;
}

}  // namespace sdfc::codegen
