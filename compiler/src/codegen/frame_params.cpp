// The per-frame parameter block. Values the camera or time changes live here,
// not in the kernel source, so a new frame never recompiles. The layout is
// the kernel ABI's (sdfc/codegen/kernel_abi.hpp).
#include <cmath>
#include <numbers>

#include "sdfc/codegen/camera_view.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc::codegen {

namespace {
using V = ir::Vec3d;
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V scale(V a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
// A path can pass the camera through its target or along up for an instant;
// a fixed axis then keeps NaN out of the frame block.
V normalize(V a) {
  double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return l > 1e-12 ? scale(a, 1.0 / l) : V{0, 1, 0};
}

V lerp(V a, V b, double u) { return {a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u, a[2] + (b[2] - a[2]) * u}; }

// Uniform Catmull-Rom through p1 (u = 0) and p2 (u = 1).
V catmull_rom(V p0, V p1, V p2, V p3, double u) {
  V r;
  double u2 = u * u, u3 = u2 * u;
  for (int i = 0; i < 3; ++i)
    r[i] = 0.5 * (2 * p1[i] + (-p0[i] + p2[i]) * u + (2 * p0[i] - 5 * p1[i] + 4 * p2[i] - p3[i]) * u2 +
                  (-p0[i] + 3 * p1[i] - 3 * p2[i] + p3[i]) * u3);
  return r;
}

// The camera at `time`: the path's keys interpolated, held before the first
// key and after the last.
ir::Camera camera_at(const ir::Camera& c, double time) {
  ir::Camera out = c;
  const auto& k = c.path;
  if (k.empty()) return out;
  if (time <= k.front().time || k.size() == 1) {
    out.position = k.front().position, out.target = k.front().target;
    return out;
  }
  if (time >= k.back().time) {
    out.position = k.back().position, out.target = k.back().target;
    return out;
  }
  size_t i = 0;
  while (k[i + 1].time < time) ++i;
  double u = (time - k[i].time) / (k[i + 1].time - k[i].time);
  if (c.interpolation == ir::Camera::Interpolation::Linear) {
    out.position = lerp(k[i].position, k[i + 1].position, u);
    out.target = lerp(k[i].target, k[i + 1].target, u);
  } else {
    const auto& a = k[i == 0 ? 0 : i - 1];
    const auto& d = k[i + 2 < k.size() ? i + 2 : k.size() - 1];
    out.position = catmull_rom(a.position, k[i].position, k[i + 1].position, d.position, u);
    out.target = catmull_rom(a.target, k[i].target, k[i + 1].target, d.target, u);
  }
  return out;
}

void put(std::vector<float>& f, int at, V v) {
  for (int i = 0; i < 3; ++i) {
    float hi = static_cast<float>(v[i]);
    f[at + i] = hi;
    f[at + abi::kLowPart + i] = static_cast<float>(v[i] - double(hi));
  }
}
}  // namespace

std::vector<float> frame_params(const ir::RenderPlan& plan, int width, int height, double time) {
  const ir::Camera c = fitted(camera_at(plan.camera, time), width, height);
  V fw = normalize(sub(c.target, c.position));
  V rt = normalize(cross(fw, c.up));
  V up = cross(rt, fw);
  const auto [tan_x, tan_y] = fov_tangents(c, width, height);
  std::vector<float> f(abi::kFrameFloats, 0.0f);
  put(f, abi::kEye, c.position);
  put(f, abi::kForward, fw);
  put(f, abi::kRight, scale(rt, tan_x));
  put(f, abi::kUp, scale(up, tan_y));
  f[abi::kPixelAngle] = static_cast<float>(2.0 * tan_y / height);
  f[abi::kTime] = static_cast<float>(time);
  f[abi::kFirstSample] = 0.0f;
  f[abi::kSampleCount] = static_cast<float>(plan.march.samples);
  double to_target = std::sqrt(sub(c.target, c.position)[0] * sub(c.target, c.position)[0] +
                               sub(c.target, c.position)[1] * sub(c.target, c.position)[1] +
                               sub(c.target, c.position)[2] * sub(c.target, c.position)[2]);
  f[abi::kFocus] = static_cast<float>(c.focus_distance > 0 ? c.focus_distance : to_target);
  return f;
}

}  // namespace sdfc::codegen
