#include "e2e_support.hpp"

#include <sdfrt/renderer.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::e2e {

using test::add;
using test::cross;
using test::mul;
using test::normalize;
using test::sub;

CameraRays::CameraRays(const ir::Camera& cam, int w, int h) : width(w), height(h) {
  origin = cam.position;
  fw_ = normalize(sub(cam.target, cam.position));
  right_ = normalize(cross(fw_, cam.up));
  up_ = cross(right_, fw_);
  // fov spans the height, the width (horizontal), or the longer side (auto).
  double tan_half = std::tan(cam.fov_degrees * std::numbers::pi / 360.0);
  bool across = cam.fov_axis == ir::Camera::FovAxis::Horizontal || (cam.fov_axis == ir::Camera::FovAxis::Auto && w > h);
  double tan_y = across ? tan_half * double(h) / double(w) : tan_half;
  right_ = mul(right_, tan_y * double(w) / double(h));
  up_ = mul(up_, tan_y);
  pixel_angle = 2 * tan_y / h;
}

V3 CameraRays::direction(int x, int y) const {
  double u = 2.0 * (x + 0.5) / width - 1.0;
  double v = 1.0 - 2.0 * (y + 0.5) / height;
  return normalize(add(fw_, add(mul(right_, u), mul(up_, v))));
}

TraceResult trace_reference(const ir::Module& m, const CameraRays& cam, const V3& dir) {
  const ir::MarchSettings& s = m.plan.march;
  TraceResult r;
  double t = 0;
  for (int i = 0; i < s.max_steps; ++i) {
    double d = reference::distance(m, add(cam.origin, mul(dir, t)));
    double foot = cam.pixel_angle * std::max(t, 1e-4);
    r.closest = std::min(r.closest, d / foot);
    r.steps = i + 1;
    if (d < s.hit_epsilon * foot) {
      r.hit = true;
      break;
    }
    t += d * s.step_factor;
    if (t >= s.max_distance) break;
  }
  r.t = t;
  return r;
}

sdfrt::FloatImage render(const ir::Module& m, int simd_width) {
  codegen::EmittedKernel k = codegen::emit_opencl(m, {simd_width, false});
  sdfrt::Renderer renderer(test::device(), sdfrt::KernelSpec{.source = k.source,
                                                             .entry = k.entry,
                                                             .simd_width = k.simd_width,
                                                             .packet_rows = k.packet_rows,
                                                             .planes = k.planes});
  const int w = m.plan.march.width, h = m.plan.march.height;
  return renderer.render(codegen::frame_params(m.plan, w, h, 0.0), w, h);
}

std::vector<std::filesystem::path> example_scenes() {
  std::vector<std::filesystem::path> v;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(SDFC_SOURCE_DIR) / "examples", ec))
    if (e.is_regular_file() && e.path().extension() == ".yaml") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace sdfc::e2e
