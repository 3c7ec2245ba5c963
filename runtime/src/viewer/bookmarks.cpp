#include "viewer/bookmarks.hpp"

#include <SDL.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "sdfc/source/write_back.hpp"

namespace sdfc::viewer {

ir::Camera with_view(const ir::Camera& scene, const ir::Camera& view) {
  ir::Camera c = scene;
  c.position = view.position;
  c.target = view.target;
  c.up = view.up;
  c.fov_degrees = view.fov_degrees;
  c.fit = false;  // the view as it is, not fitted again
  c.path.clear();
  return c;
}

std::optional<ir::Camera> Bookmarks::recall(int key, const ir::Camera& scene) const {
  for (const auto& b : list_) {
    if (b.key != key) continue;
    ir::Camera view;
    view.position = b.position, view.target = b.target, view.up = b.up, view.fov_degrees = b.fov_degrees;
    return with_view(scene, view);
  }
  return std::nullopt;
}

namespace {
// 12 digits: a view needs no more, and a target the rig computed (0.5999999999999979) is written 0.6.
double kept(double x) { return std::strtod(fmt::format("{:.12g}", x).c_str(), nullptr); }
ir::Vec3d kept(const ir::Vec3d& v) { return {kept(v[0]), kept(v[1]), kept(v[2])}; }
}  // namespace

void Bookmarks::store(int key, const ir::Camera& view) {
  // Kept as the file holds them, so a view recalled now equals the one recalled after a reload.
  frontend::Bookmark b{key, kept(view.position), kept(view.target), kept(view.up), kept(view.fov_degrees)};
  auto it = std::find_if(list_.begin(), list_.end(), [&](const frontend::Bookmark& x) { return x.key == key; });
  if (it != list_.end()) *it = b;
  else list_.push_back(b);
  std::sort(list_.begin(), list_.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
}

std::string Bookmarks::yaml() const {
  // Numbers as the shortest text that reads back exactly: the file holds what store() kept.
  auto v = [](const ir::Vec3d& a) { return fmt::format("[{}, {}, {}]", yaml_number(a[0]), yaml_number(a[1]), yaml_number(a[2])); };
  std::string out = "bookmarks:  # views kept by sdfc view: Shift+1 ... Shift+9 keeps one, 1 ... 9 recalls it\n";
  for (const auto& b : list_)
    out += fmt::format("  - {{key: {}, position: {}, target: {}, up: {}, fov: {}}}\n", b.key, v(b.position), v(b.target),
                       v(b.up), yaml_number(b.fov_degrees));
  return out;
}

int bookmark_key(int sym) {
  if (sym >= SDLK_1 && sym <= SDLK_9) return sym - SDLK_1 + 1;
  if (sym >= SDLK_KP_1 && sym <= SDLK_KP_9) return sym - SDLK_KP_1 + 1;
  return 0;
}

}  // namespace sdfc::viewer
