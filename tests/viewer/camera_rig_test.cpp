// The viewer's camera: speed follows the distance to the surface, orbit
// keeps the target, and the C-key YAML reads back as the same camera.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "sdfc/compile.hpp"
#include "viewer/camera_rig.hpp"

namespace sdfc::viewer {
namespace {

ir::Camera start_camera() {
  ir::Camera c;
  c.position = {0, -4, 1};
  c.target = {0, 0, 0};
  c.up = {0, 0, 1};
  c.fov_degrees = 50;
  return c;
}

double dist(const ir::Vec3d& a, const ir::Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(CameraRig, FlySpeedScalesWithTheDistanceToTheSurface) {
  MotionInput fwd;
  fwd.forward = 1;
  CameraRig far(start_camera()), near(start_camera());
  far.apply(fwd, 0.1, 2.0);
  near.apply(fwd, 0.1, 0.001);
  double moved_far = dist(far.position(), start_camera().position);
  double moved_near = dist(near.position(), start_camera().position);
  EXPECT_NEAR(moved_far, 0.2, 1e-12);
  EXPECT_NEAR(moved_near, 0.0001, 1e-12);
  // Shift is five times faster; the wheel scales the speed.
  CameraRig fast(start_camera());
  fwd.fast = true;
  fast.scale_speed(2.0);
  fast.apply(fwd, 0.1, 2.0);
  EXPECT_NEAR(dist(fast.position(), start_camera().position), 2.0, 1e-12);
}

TEST(CameraRig, OrbitKeepsTheTargetAndLooksAtIt) {
  CameraRig rig(start_camera());
  rig.toggle_mode();
  ASSERT_EQ(rig.mode(), CameraMode::Orbit);
  MotionInput in;
  in.right = 1;
  in.yaw = 0.3;
  in.pitch = 0.2;
  for (int i = 0; i < 10; ++i) rig.apply(in, 0.05, 1.0);
  ir::Camera c = rig.camera();
  EXPECT_NEAR(dist(c.target, {0, 0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(dist(c.position, {0, 0, 0}), dist(start_camera().position, {0, 0, 0}), 1e-9);
  EXPECT_GT(dist(c.position, start_camera().position), 0.5);
  // W moves in towards the target.
  MotionInput zoom;
  zoom.forward = 1;
  rig.apply(zoom, 0.5, 1.0);
  EXPECT_NEAR(dist(rig.camera().position, {0, 0, 0}), dist(start_camera().position, {0, 0, 0}) - 0.5, 1e-9);
}

TEST(CameraRig, PitchStopsShortOfThePole) {
  CameraRig rig(start_camera());
  MotionInput look;
  look.pitch = 0.2;
  for (int i = 0; i < 50; ++i) rig.apply(look, 0.016, 1.0);
  ir::Camera c = rig.camera();
  double fz = (c.target[2] - c.position[2]) / dist(c.target, c.position);
  EXPECT_LT(fz, 1.0);
  EXPECT_GT(fz, 0.97);  // within a step of the 89-degree limit
}

TEST(CameraRig, YamlReadsBackAsTheSameCamera) {
  CameraRig rig(start_camera());
  MotionInput in;
  in.forward = 1;
  in.right = 0.5;
  in.yaw = 0.4;
  rig.apply(in, 0.3, 1.7);
  ir::Camera c = rig.camera();
  auto path = std::filesystem::path(::testing::TempDir()) / "camera_yaml_roundtrip.yaml";
  std::ofstream(path) << camera_yaml(c) << "\nscene:\n  sphere: {radius: 1}\n";
  ir::Module m = build_module(load_scene_source(path.string(), {}), path.string());
  ir::Camera back = m.plan.camera;
  EXPECT_LT(dist(back.position, c.position), 1e-5);
  EXPECT_LT(dist(back.target, c.target), 1e-5);
  EXPECT_LT(dist(back.up, c.up), 1e-5);
  EXPECT_NEAR(back.fov_degrees, c.fov_degrees, 1e-9);
}

}  // namespace
}  // namespace sdfc::viewer
