#pragma once
// What the orbit-trap conformance tests share: a kernel that reads
// scene_trap at given points, points on rays just outside a fractal's
// surface (where the renderer reads the trap), and the scene's fractal node.
#include <stdexcept>
#include <random>
#include <string>
#include <vector>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::test {

inline std::string trap_probe_kernel(const ir::Module& m, int width) {
  return codegen::emit_opencl(m, {width, false}).source + R"(
__kernel void trap_probe(__global const float* px, __global const float* py, __global const float* pz,
                         __global float* out)
{
    const int i = get_global_id(0) * SDFC_WIDTH;
    vec3 p = v3(LOAD_REAL(px + i), LOAD_REAL(py + i), LOAD_REAL(pz + i));
    STORE_REAL(scene_trap(p), out + i);
}
)";
}

// Up to `most` points: `per_ray` steps back from the surface along rays
// into a ball of `radius` around the set.
inline std::vector<V3> points_near_surface(const ir::Module& m, double radius, std::mt19937_64& rng, int rays,
                                           size_t most, int per_ray) {
  std::vector<V3> pts;
  for (int attempt = 0; attempt < rays && pts.size() < most; ++attempt) {
    auto [o, rd] = random_ray(rng, {0, 0, 0}, 2.5 * radius, 0.4 * radius);
    auto f = [&](const V3& x) { return reference::distance(m, x); };
    if (auto t = trace_to_surface(f, o, rd, 1e-4 * radius, 5 * radius))
      for (int k = 0; k < per_ray; ++k) pts.push_back(to_float_point(add(o, mul(rd, *t - k * 2e-4 * radius))));
  }
  return pts;
}

inline const ir::Node& fractal_of(const ir::Module& m) {
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (ir::info(m.graph->node(id).kind).category == ir::Category::Fractal) return m.graph->node(id);
  throw std::logic_error("no fractal in the scene");
}

}  // namespace sdfc::test
