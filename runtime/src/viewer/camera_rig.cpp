#include "viewer/camera_rig.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sdfc::viewer {

namespace {
using V = ir::Vec3d;
V add(V a, V b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V scale(V a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double length(V a) { return std::sqrt(dot(a, a)); }
V normalize(V a) { return scale(a, 1.0 / length(a)); }
// Rodrigues: v rotated by `angle` about the unit axis k.
V rotate(V v, V k, double angle) {
  double c = std::cos(angle), s = std::sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}
// Stop short of the poles so the basis (forward x up) never degenerates.
const double kMaxPitchSin = std::sin(89.0 * std::numbers::pi / 180.0);
constexpr double kOrbitTurnRate = 1.0;  // rad/s for keyboard orbiting
}  // namespace

CameraRig::CameraRig(const ir::Camera& start) { reset(start); }

void CameraRig::reset(const ir::Camera& start) {
  pos_ = start.position;
  V d = sub(start.target, start.position);
  focus_ = length(d);
  fwd_ = normalize(d);
  up_ = normalize(start.up);
  fov_ = start.fov_degrees;
  fov_axis_ = start.fov_axis;
}

void CameraRig::turn(double yaw, double pitch) {
  if (yaw != 0) fwd_ = normalize(rotate(fwd_, up_, -yaw));
  if (pitch != 0) {
    V right = normalize(cross(fwd_, up_));
    V turned = normalize(rotate(fwd_, right, pitch));
    if (std::abs(dot(turned, up_)) < kMaxPitchSin) fwd_ = turned;
  }
}

bool CameraRig::apply(const MotionInput& in, double dt, double surface_distance) {
  bool moves = in.forward != 0 || in.right != 0 || in.up != 0;
  if (!moves && in.yaw == 0 && in.pitch == 0) return false;
  double boost = in.fast ? 5.0 : 1.0;
  // Floor: inside a surface or exactly on it the DE is <= 0; keep creeping.
  double step = speed_ * boost * std::max(std::abs(surface_distance), 1e-6) * dt;
  if (mode_ == CameraMode::Fly) {
    turn(in.yaw, in.pitch);
    V right = normalize(cross(fwd_, up_));
    pos_ = add(pos_, scale(fwd_, in.forward * step));
    pos_ = add(pos_, scale(right, in.right * step));
    pos_ = add(pos_, scale(up_, in.up * step));
    return true;
  }
  // Orbit: keys and mouse turn around the target, W/S move in and out.
  V target = add(pos_, scale(fwd_, focus_));
  double rate = kOrbitTurnRate * boost * dt;
  turn(in.yaw - in.right * rate, in.pitch - in.up * rate);  // D and E move the camera right and up
  focus_ = std::max(focus_ - in.forward * step, 1e-6);
  pos_ = sub(target, scale(fwd_, focus_));
  return true;
}

void CameraRig::toggle_mode() { mode_ = mode_ == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly; }

void CameraRig::scale_speed(double factor) { speed_ = std::clamp(speed_ * factor, 1e-3, 1e3); }

void CameraRig::orbit_to(const ir::Camera& start, double angle) {
  V up = normalize(start.up);
  V offset = rotate(sub(start.position, start.target), up, angle);
  pos_ = add(start.target, offset);
  V d = sub(start.target, pos_);
  focus_ = length(d);
  fwd_ = normalize(d);
  up_ = up;
  fov_ = start.fov_degrees;
}

ir::Camera CameraRig::camera() const {
  ir::Camera c;
  c.position = pos_;
  c.target = add(pos_, scale(fwd_, focus_));
  c.up = up_;
  c.fov_degrees = fov_;
  c.fov_axis = fov_axis_;
  return c;
}

std::string camera_yaml(const ir::Camera& c) {
  auto v = [](const V& a) { return fmt::format("[{:.6g}, {:.6g}, {:.6g}]", a[0], a[1], a[2]); };
  const char* axis = c.fov_axis == ir::Camera::FovAxis::Horizontal ? ", fov_axis: horizontal"
                     : c.fov_axis == ir::Camera::FovAxis::Auto     ? ", fov_axis: auto"
                                                                    : "";
  return fmt::format("camera: {{position: {}, target: {}, up: {}, fov: {:.6g}{}}}", v(c.position), v(c.target),
                     v(c.up), c.fov_degrees, axis);
}

}  // namespace sdfc::viewer
