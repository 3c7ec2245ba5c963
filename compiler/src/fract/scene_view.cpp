// The camera, image and march settings of an imported scene.
//
// Mandelbulber's three-point camera looks from `camera` at `target` with
// `camera_top` up; `fov` is the image height at distance 1 in files before
// 2.21 and degrees after. It casts rays through pixel corners where sdfc
// casts them through centres, so the imported target moves by half a pixel
// (left and up) to show the same picture. A ray hits when the estimate
// falls below 1 / detail_level of a pixel's footprint: sdfc's hit_epsilon.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "import_parts.hpp"

namespace sdfc::fract {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

}  // namespace

// Degrees of the vertical view.
double vertical_fov_degrees(const Params& main, double version) {
  double fov = main.number("fov");
  double deg = version < 2.21 ? std::atan(fov / 2.0) * 360.0 / M_PI : fov;
  if (!(deg > 0 && deg < 179)) fail(main.loc("fov"), fmt::format("fov {} is outside the pinhole camera's range", num(fov)));
  return deg;
}

// The target, or where camera_rotation looks when the file's target sits on
// the camera (camera_distance_to_target ~ 1e-10 in some files): yaw about z,
// then pitch about x, of the camera's forward axis +y.
Vec3 view_target(const Params& main) {
  Vec3 p = main.vec3("camera"), t = main.vec3("target");
  if (length(sub(t, p)) > 1e-6 * std::max(1.0, length(p))) return t;
  Vec3 r = main.vec3("camera_rotation");
  double yaw = r[0] * M_PI / 180, pitch = r[1] * M_PI / 180;
  Vec3 f = {-std::sin(yaw) * std::cos(pitch), std::cos(yaw) * std::cos(pitch), std::sin(pitch)};
  return {p[0] + f[0], p[1] + f[1], p[2] + f[2]};
}

CameraFrame camera_frame(const Params& main) { return frame_of(main.vec3("camera"), view_target(main), main.vec3("camera_top"), main); }

CameraFrame frame_of(const Vec3& position, const Vec3& target, const Vec3& top, const Params& main) {
  CameraFrame c;
  c.position = position;
  c.target = target;
  Vec3 f = sub(c.target, c.position);
  double d = length(f);
  if (!(d > 0)) fail(main.loc("target"), "camera and target are the same point");
  c.forward = scaled(f, 1 / d);
  c.right = cross(c.forward, top);
  double r = length(c.right);
  if (!(r > 1e-9)) fail(main.loc("camera_top"), "camera_top is parallel to the view direction");
  c.right = scaled(c.right, 1 / r);
  c.up = cross(c.right, c.forward);
  c.distance = d;
  return c;
}

std::string import_view(const File& file, const Params& main, const std::string& path, ImportContext& w) {
  int type = main.integer("perspective_type");
  if (type != 0)
    fail(main.loc("perspective_type"), fmt::format("perspective_type {} (fish eye or equirectangular) is not supported "
                                                   "yet; sdfc has the three-point (pinhole) camera, 0", type));
  if (main.given("stereo_enabled") && main.boolean("stereo_enabled")) w.add("stereo: not imported (one eye's view)");
  if (main.given("DOF_enabled") && main.boolean("DOF_enabled")) w.add("depth of field (DOF_*): not imported");
  int width = main.integer("image_width"), height = main.integer("image_height");
  if (width < 1 || width > 16384) fail(main.loc("image_width"), "image_width must be 1 ... 16384");
  if (height < 1 || height > 16384) fail(main.loc("image_height"), "image_height must be 1 ... 16384");
  double fov = vertical_fov_degrees(main, file.version);
  // In the legacy coordinate system the reflected scene is seen with up
  // reversed (see ImportContext).
  Vec3 top = w.world(main.vec3("camera_top"));
  if (w.mirror_y) top = {-top[0], -top[1], -top[2]};
  CameraFrame c = frame_of(w.world(main.vec3("camera")), w.world(view_target(main)), top, main);
  // Mandelbulber's pixel (i, j) looks through its top-left corner: half a
  // pixel left of and above sdfc's centre.
  double pixel = 2 * std::tan(fov * M_PI / 360.0) / height * c.distance;
  Vec3 target = c.target;
  for (int k = 0; k < 3; ++k) target[size_t(k)] += 0.5 * pixel * (c.up[size_t(k)] - c.right[size_t(k)]);

  std::string o = "camera:\n";
  if (path.empty()) {
    const char* mirrored = w.mirror_y ? ", mirrored in y (legacy_coordinate_system)" : "";
    o += commented("  position: " + vec(c.position), std::string("camera") + mirrored);
    o += commented("  target: " + vec(target),
                   std::string("target") + mirrored + ", half a pixel up and left: Mandelbulber samples pixel corners");
  } else {
    o += path;
  }
  o += commented("  up: " + vec(top), w.mirror_y ? "camera_top, mirrored: legacy_coordinate_system" : "camera_top");
  o += commented("  fov: " + num(fov), file.version < 2.21 ? fmt::format("fov {} (image height at distance 1)", num(main.number("fov")))
                                                           : std::string("fov (degrees)"));
  o += "render:\n";
  o += commented("  width: " + std::to_string(width), "image_width");
  o += commented("  height: " + std::to_string(height), "image_height");
  double detail = main.number("detail_level");
  if (!(detail > 0)) fail(main.loc("detail_level"), "detail_level must be positive");
  double eps = 1.0 / detail;
  if (eps > 1000 || eps < 1e-6) {
    eps = std::clamp(eps, 1e-6, 1000.0);
    w.add(fmt::format("detail_level {}: sdfc's hit_epsilon is 1e-6 ... 1000 pixels; {} is used", num(detail), num(eps)));
  }
  o += commented("  hit_epsilon: " + num(eps), "1 / detail_level (pixels)");
  double de = main.number("DE_factor");
  if (!(de > 0)) fail(main.loc("DE_factor"), "DE_factor must be positive");
  if (de > 2) w.add(fmt::format("DE_factor {}: sdfc's step_factor is at most 2; 2 is used", num(de)));
  o += commented("  step_factor: " + num(std::min(de, 2.0)), "DE_factor");
  int steps = int(std::clamp(std::ceil(500.0 / std::min(de, 2.0)), 256.0, 20000.0));
  o += commented("  max_steps: " + std::to_string(steps), "500 / DE_factor (Mandelbulber has no step cap of its own)");
  o += commented("  max_distance: " + num(main.number("view_distance_max")), "view_distance_max");
  o += commented("  gamma: 1", "Mandelbulber writes its shading as it is (gamma 1)");
  return o;
}

}  // namespace sdfc::fract
