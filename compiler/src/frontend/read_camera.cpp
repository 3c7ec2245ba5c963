// The camera section: a still view (position, target, up) or a path of
// keys, the field of view and its axis, depth of field, and camera.fit.
#include "read_camera.hpp"

#include <fmt/format.h>

#include <cmath>

#include "too_small.hpp"

namespace sdfc::frontend {

namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

void check_view(ValueReader& r, const SourceLoc& loc, const SourceLoc& up_loc, const Vec3d& position, const Vec3d& target,
                const Vec3d& up, const std::string& what) {
  Vec3d f{target[0] - position[0], target[1] - position[1], target[2] - position[2]};
  double len = std::sqrt(dot(f, f));
  if (len < 1e-9) {
    r.sink().error(loc, what + ": target is at the camera position, so there is no view direction", "move the target");
    return;
  }
  if (std::fabs(dot(f, up)) / len > 0.9999)
    r.sink().error(up_loc, what + ": up is parallel to the view direction",
                   "choose an up vector across the view, e.g. [0, 0, 1] for a camera looking along y");
}

namespace {

void read_camera_path(ValueReader& r, const SourceValue& v, ir::Camera& cam, const SourceLoc& up_loc) {
  MapReader m(r, v, "camera.path", {"keys", "interpolation"});
  cam.interpolation = m.word("interpolation", "linear", {"linear", "catmull_rom"}) == "catmull_rom"
                          ? ir::Camera::Interpolation::CatmullRom
                          : ir::Camera::Interpolation::Linear;
  const SourceValue* keys = m.require("keys");
  if (!keys) return;
  if (!keys->is_seq() || keys->items.empty()) {
    r.sink().error(keys->loc, "camera.path.keys: expected a list of keys, e.g. '- {time: 0, position: [0, -5, 1], target: [0, 0, 0]}'", "");
    return;
  }
  for (const auto& item : keys->items) {
    MapReader k(r, item, "camera.path key", {"time", "position", "target"});
    ir::CameraKey key;
    if (k.require("time")) key.time = k.number("time", 0);
    if (k.require("position")) key.position = k.vec3("position", key.position);
    if (k.require("target")) key.target = k.vec3("target", key.target);
    if (!cam.path.empty() && key.time <= cam.path.back().time)
      r.sink().error(item.loc, fmt::format("camera.path: key times must increase, but {} follows {}", key.time, cam.path.back().time), "");
    check_view(r, item.loc, up_loc, key.position, key.target, cam.up, "camera.path key");
    cam.path.push_back(key);
  }
}

}  // namespace

void read_camera(ValueReader& r, const SourceValue& v, ir::Camera& cam) {
  MapReader m(r, v, "camera", {"position", "target", "up", "fov", "fov_axis", "aperture", "focus_distance", "path",
                               "fit", "direction"});
  cam.loc = v.loc;
  cam.position = m.vec3("position", cam.position);
  cam.target = m.vec3("target", cam.target);
  cam.up = m.direction("up", cam.up);
  cam.fov_degrees = m.number("fov", cam.fov_degrees, {0, 179, true});
  std::string axis = m.word("fov_axis", "vertical", {"vertical", "horizontal", "auto"});
  cam.fov_axis = axis == "horizontal" ? ir::Camera::FovAxis::Horizontal
                 : axis == "auto"     ? ir::Camera::FovAxis::Auto
                                      : ir::Camera::FovAxis::Vertical;
  cam.fit = m.word("fit", "false", {"false", "true"}) == "true";
  if (const SourceValue* dir = m.get("direction")) {
    cam.direction = m.direction("direction", cam.direction);
    if (!cam.fit)
      r.sink().error(dir->loc, "camera.direction is the view direction of camera.fit",
                     "add 'fit: true', or give position and target instead");
    else if (m.get("target"))
      r.sink().error(dir->loc, "camera: give either a direction or a target for fit: true, not both", "");
    cam.target = {cam.position[0] + cam.direction[0], cam.position[1] + cam.direction[1],
                  cam.position[2] + cam.direction[2]};
  }
  if (cam.fov_degrees > 0 && cam.fov_degrees < 1e-6)  // the pixel footprint would underflow: no ray hits
    too_small(r, *m.get("fov"), "camera.fov", cam.fov_degrees, 1e-6);
  cam.aperture = m.number("aperture", cam.aperture, Range::non_negative(1e3));
  cam.focus_distance = m.number("focus_distance", cam.focus_distance, Range::non_negative());
  const SourceLoc up_loc = m.get("up") ? m.get("up")->loc : v.loc;
  if (const SourceValue* path = m.get("path")) {
    if (m.get("position") || m.get("target"))
      r.sink().error(path->loc, "camera: give either position and target or a path, not both",
                     "move position and target into the path's keys");
    if (cam.fit) r.sink().error(path->loc, "camera: fit: true places a still camera; a path moves it", "remove 'fit' or the path");
    read_camera_path(r, *path, cam, up_loc);
    if (!cam.path.empty()) {
      cam.position = cam.path.front().position;  // the static view is the first key
      cam.target = cam.path.front().target;
    }
    return;
  }
  // A position or target that is no list of three numbers was reported as
  // such and read as zero: comparing it would add a false "target is at the
  // camera position".
  auto three = [&](const char* key) {
    const SourceValue* x = m.get(key);
    return !x || (x->is_seq() && x->items.size() == 3);
  };
  if (three("position") && three("target")) check_view(r, v.loc, up_loc, cam.position, cam.target, cam.up, "camera");
}

}  // namespace sdfc::frontend
