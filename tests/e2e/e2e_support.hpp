#pragma once
// End-to-end helpers: the camera's rays computed here from the scene's camera
// (independently of frame_params), a CPU sphere tracer over the reference
// evaluator, image statistics, and rendering a module on the device.
#include <sdfrt/float_image.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "sdfc/ir/module.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::e2e {

using test::V3;

// The pinhole camera of the kernel: pixel centre (x + 0.5, y + 0.5),
// u = 2 px / W - 1, v = 1 - 2 py / H (row 0 at the top),
// dir = normalize(fw + u * right * tan(fov/2) * aspect + v * up * tan(fov/2))
// for a vertical fov (camera.fov_axis; a horizontal one divides by aspect),
// with fw = normalize(target - position), right = normalize(fw x up_hint),
// up = right x fw.
struct CameraRays {
  CameraRays(const ir::Camera& cam, int width, int height);
  V3 origin;
  V3 direction(int x, int y) const;
  double pixel_angle;  // 2 tan(fov/2) / height: footprint per unit distance
  int width, height;

 private:
  V3 fw_, right_, up_;
};

// Sphere tracing over the double-precision reference, with the kernel's
// rules (hit when d < hit_epsilon * pixel_angle * max(t, 1e-4); step d *
// step_factor; give up after max_steps or past max_distance).
struct TraceResult {
  bool hit = false;
  double t = 0;
  int steps = 0;
  double closest = 1e300;  // min over the march of d / (pixel_angle * t): how near the ray came, in pixels
};
TraceResult trace_reference(const ir::Module& m, const CameraRays& cam, const V3& dir);

// Renders the module on the test device at its plan's size.
sdfrt::FloatImage render(const ir::Module& m, int simd_width);

// Example scenes: every *.yaml under <source>/examples, sorted.
std::vector<std::filesystem::path> example_scenes();

}  // namespace sdfc::e2e
