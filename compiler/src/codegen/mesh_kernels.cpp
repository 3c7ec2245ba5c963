// The sampling entries of `sdfc mesh`, appended to the scene's own render
// kernel so they call exactly the scene_dist / material code renders use.
// No scene text reaches this code: only the emitted functions' names.
#include "sdfc/codegen/emit_mesh_kernels.hpp"

#include <string>

#include "code_writer.hpp"
#include "object_set_emitter.hpp"
#include "scene_emitter.hpp"

namespace sdfc::codegen {

namespace {

// The scene, offset by the iso distance, cut to the grid's box: max with the
// box's exact distance keeps a cut solid closed (the cut stays at the box
// whatever the offset), and the result is still a distance bound.
const char* kClippedDistance = R"(
// ---- mesh sampling: the scene distance, cut to the mesh's box ----
real sdfc_mesh_distance(TIME_PARAM vec3 p, __global const float* g)
{
    real d = scene_dist(TIME_ARG p);
    real qx = fabs(p.x - (real)((scalar)(0.5f * (g[4] + g[7])))) - (real)((scalar)(0.5f * (g[7] - g[4])));
    real qy = fabs(p.y - (real)((scalar)(0.5f * (g[5] + g[8])))) - (real)((scalar)(0.5f * (g[8] - g[5])));
    real qz = fabs(p.z - (real)((scalar)(0.5f * (g[6] + g[9])))) - (real)((scalar)(0.5f * (g[9] - g[6])));
    real ox = fmax(qx, (real)(0.0f)), oy = fmax(qy, (real)(0.0f)), oz = fmax(qz, (real)(0.0f));
    real box = sqrt(ox * ox + oy * oy + oz * oz) + fmin(fmax(qx, fmax(qy, qz)), (real)(0.0f));
    return fmax(d - (real)((scalar)g[11]), box);
}

__kernel void sdfc_mesh_points(__global const float* px, __global const float* py, __global const float* pz,
                               __global float* out, __global const float* g)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
    TIME_FROM_GRID
    STORE_REAL(sdfc_mesh_distance(TIME_ARG p, g), out + i);
}

// one work-item: SDFC_WIDTH consecutive voxels of an 8x8x8 block
__kernel void sdfc_mesh_blocks(__global const int* blocks, __global float* out, __global const float* g)
{
    const int gid = get_global_id(0);
    const int b = gid / (512 / SDFC_WIDTH);
    const int first = (gid % (512 / SDFC_WIDTH)) * SDFC_WIDTH;
    real idx = (real)((scalar)first) + LANE_IDS;  // small integers: exact in float
    real ix = floor(idx * (real)(0.015625f));
    real rest = idx - ix * (real)(64.0f);
    real iy = floor(rest * (real)(0.125f));
    real iz = rest - iy * (real)(8.0f);
    const scalar h = (scalar)g[3];
    vec3 p = v3((real)((scalar)g[0]) + ((real)((scalar)(8 * blocks[3 * b])) + ix) * h,
                (real)((scalar)g[1]) + ((real)((scalar)(8 * blocks[3 * b + 1])) + iy) * h,
                (real)((scalar)g[2]) + ((real)((scalar)(8 * blocks[3 * b + 2])) + iz) * h);
    TIME_FROM_GRID
    STORE_REAL(sdfc_mesh_distance(TIME_ARG p, g), out + 512 * b + first);
}
)";

std::string colour_kernel(const std::string& albedo_code) {
  return R"(
// ---- mesh colour: the albedo shading starts from, at surface points ----
__kernel void sdfc_mesh_colour(__global const float* px, __global const float* py, __global const float* pz,
                               __global float* out, const int n, __global const float* g)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
    TIME_FROM_GRID
    vec3 albedo;
)" + albedo_code + R"(    STORE_REAL(albedo.x, out + i);
    STORE_REAL(albedo.y, out + n + i);
    STORE_REAL(albedo.z, out + 2 * n + i);
}
)";
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
}

}  // namespace

EmittedKernel emit_mesh_kernels(const ir::Module& m, int simd_width) {
  std::string albedo;
  if (m.analyses.material_blend) {
    albedo = m.analyses.coloring_geometry
                 ? "    mat_record r;\n    (void)scene_material(TIME_ARG p, normal_central(TIME_ARG p, K(1e-4f)), &r);\n"
                   "    albedo = r.albedo;\n"
                 : "    mat_record r;\n    (void)scene_material(TIME_ARG p, &r);\n    albedo = r.albedo;\n";
  } else {
    // the same material_of call shade_surface makes, with the orbit trap when the scene has one
    const bool trap = m.analyses.orbit_traps;
    albedo = "    real id, specular, shininess;\n    (void)scene_dist_mat(TIME_ARG p, &id);\n";
    if (trap) albedo += "    real trap = scene_trap(TIME_ARG p);\n";
    albedo += std::string("    material_of(id, &albedo, &specular, &shininess") + (trap ? ", trap" : "") +
              (m.analyses.coloring_geometry ? ", p, normal_central(TIME_ARG p, K(1e-4f))" : "") + ");\n";
  }
  std::string entries = std::string(kClippedDistance) + colour_kernel(albedo);
  replace_all(entries, "TIME_FROM_GRID",
              std::string(m.analyses.uses_time ? "const scalar time = (scalar)g[10];" : "(void)g[10];") +
                  (detail::has_object_sets(m) ? "\n    __global const float* scene_data = g + 12;  // the object sets' numbers" : ""));
  EmitOptions opt;
  opt.simd_width = simd_width;
  opt.extra_entries = entries;
  EmittedKernel k = emit_opencl(m, opt);
  k.entry = "sdfc_mesh_blocks";
  return k;
}

}  // namespace sdfc::codegen
