#pragma once
// The viewer's camera: first-person fly or orbit around a target. It only
// produces an ir::Camera; the frame block built from it moves the view, so
// camera motion never recompiles the kernel.
#include <string>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::viewer {

enum class CameraMode { Fly, Orbit };

// One frame of user input, already decoded from keys and mouse.
struct MotionInput {
  double forward = 0, right = 0, up = 0;  // -1, 0 or 1 from held keys
  double yaw = 0, pitch = 0;              // radians: + turns right, + looks up
  bool fast = false;                      // Shift
};

class CameraRig {
 public:
  explicit CameraRig(const ir::Camera& start);

  // Back to `start` (R key, and the first camera of the scene); the mode stays.
  void reset(const ir::Camera& start);
  // Moves by one frame of input. Translation speed is speed() * |DE at the
  // camera| per second, so approaching a surface slows down by itself.
  // Returns whether the camera changed.
  bool apply(const MotionInput& in, double dt_seconds, double surface_distance);
  // Tab: fly <-> orbit. Entering orbit keeps the view: the target becomes
  // the point `focus` ahead of the camera.
  void toggle_mode();
  // Mouse wheel: multiplies the speed (clamped to [1e-3, 1e3]).
  void scale_speed(double factor);
  // Places the camera on a circle around the target (benchmark orbit):
  // `angle` radians about the up axis from the start position.
  void orbit_to(const ir::Camera& start, double angle);

  CameraMode mode() const noexcept { return mode_; }
  double speed() const noexcept { return speed_; }
  const ir::Vec3d& position() const noexcept { return pos_; }
  ir::Camera camera() const;

 private:
  void turn(double yaw, double pitch);

  ir::Vec3d pos_{}, fwd_{}, up_{};
  double fov_ = 45;
  ir::Camera::FovAxis fov_axis_ = ir::Camera::FovAxis::Vertical;
  double focus_ = 1;  // distance to the target along the view
  CameraMode mode_ = CameraMode::Fly;
  double speed_ = 1;
};

// `camera: {position: [...], target: [...], up: [...], fov: F}`, ready to
// paste into a scene file (C key).
std::string camera_yaml(const ir::Camera& c);

}  // namespace sdfc::viewer
