// fov_axis and camera.fit (see camera_view.hpp).
#include "sdfc/codegen/camera_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sdfc::codegen {

namespace {
using V = ir::Vec3d;
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V normalize(V a) {
  double l = std::sqrt(dot(a, a));
  return l > 1e-12 ? V{a[0] / l, a[1] / l, a[2] / l} : V{0, 1, 0};
}
}  // namespace

std::array<double, 2> fov_tangents(const ir::Camera& c, int width, int height) {
  const double t = std::tan(c.fov_degrees * std::numbers::pi / 360.0);
  const double aspect = double(width) / double(height);
  bool horizontal = c.fov_axis == ir::Camera::FovAxis::Horizontal ||
                    (c.fov_axis == ir::Camera::FovAxis::Auto && width > height);
  return horizontal ? std::array<double, 2>{t, t / aspect} : std::array<double, 2>{t * aspect, t};
}

ir::Camera fitted(const ir::Camera& c, int width, int height) {
  if (!c.fit || !c.has_fit_box) return c;
  const bool given = dot(c.direction, c.direction) > 0;
  const V fw = normalize(given ? c.direction : V{c.target[0] - c.position[0], c.target[1] - c.position[1],
                                                  c.target[2] - c.position[2]});
  const V rt = normalize(cross(fw, c.up));
  const V up = cross(rt, fw);
  const auto [tx, ty] = fov_tangents(c, width, height);
  V centre;
  for (int i = 0; i < 3; ++i) centre[i] = 0.5 * (c.fit_lo[i] + c.fit_hi[i]);
  // A corner at camera coordinates (x, y, z) around the centre, seen from
  // distance D behind it, projects to x / (D + z): inside the frame when
  // D >= |x| / (fill tx) - z, and the same for y.
  double d = 0;
  for (int k = 0; k < 8; ++k) {
    V p{(k & 1 ? c.fit_hi[0] : c.fit_lo[0]) - centre[0], (k & 2 ? c.fit_hi[1] : c.fit_lo[1]) - centre[1],
        (k & 4 ? c.fit_hi[2] : c.fit_lo[2]) - centre[2]};
    double x = dot(p, rt), y = dot(p, up), z = dot(p, fw);
    d = std::max({d, std::fabs(x) / (kFitFill * tx) - z, std::fabs(y) / (kFitFill * ty) - z, 1e-3 - z});
  }
  ir::Camera out = c;
  out.target = centre;
  for (int i = 0; i < 3; ++i) out.position[i] = centre[i] - fw[i] * d;
  out.path.clear();
  return out;
}

}  // namespace sdfc::codegen
