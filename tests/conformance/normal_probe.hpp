#pragma once
// A probe kernel for render.normals: dual: per point the cosine between the
// dual normal and a 6-tap central difference of the same kernel's
// scene_dist (shared by the dual-normal suites).
#include <string>

#include "sdfc_test_support.hpp"

namespace sdfc {

// The emitted kernel plus a probe that writes both normals per point.
inline std::string normal_kernel(const ir::Module& m, int width, const char* h = "1e-3f") {
  std::string src = codegen::emit_opencl(m, {width, false}).source;
  return src + "#define SDFC_PROBE_H " + h + "\n" + R"(
__kernel void normal_probe(__global const float* px, __global const float* py, __global const float* pz,
                           __global float* out)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
    vec3 nd = scene_normal_dual(p);
    const scalar h = K(SDFC_PROBE_H);
    vec3 nc = v3_normalize(v3(scene_dist(v3(p.x + h, p.y, p.z)) - scene_dist(v3(p.x - h, p.y, p.z)),
                              scene_dist(v3(p.x, p.y + h, p.z)) - scene_dist(v3(p.x, p.y - h, p.z)),
                              scene_dist(v3(p.x, p.y, p.z + h)) - scene_dist(v3(p.x, p.y, p.z - h))));
    STORE_REAL(v3_dot(nd, nc), out + i);
}
)";
}

}  // namespace sdfc
