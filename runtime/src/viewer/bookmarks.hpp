#pragma once
// Camera bookmarks: Shift+1 ... Shift+9 keeps the current view under the key,
// 1 ... 9 goes back to it. They live in the scene file's `bookmarks:` list
// (read by the front end when the scene loads; written by LiveValues).
#include <optional>
#include <string>
#include <vector>

#include "sdfc/frontend/bookmarks.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::viewer {

class Bookmarks {
 public:
  explicit Bookmarks(std::vector<frontend::Bookmark> saved = {}) : list_(std::move(saved)) {}

  // The view under `key` on top of `scene` (the scene's camera keeps its
  // fov axis, lens and so on); nullopt when the key holds none.
  std::optional<ir::Camera> recall(int key, const ir::Camera& scene) const;
  // Keeps `view` under `key`, replacing what it held.
  void store(int key, const ir::Camera& view);
  const std::vector<frontend::Bookmark>& list() const noexcept { return list_; }
  // The `bookmarks:` section as the file holds it, one line per view, by key.
  std::string yaml() const;

 private:
  std::vector<frontend::Bookmark> list_;
};

// The scene's camera (its fov axis, lens ...) looking from `view`'s place, direction and fov.
ir::Camera with_view(const ir::Camera& scene, const ir::Camera& view);

// 1 ... 9 for the digit keys (top row or keypad), 0 for any other key.
int bookmark_key(int sdl_keycode);

}  // namespace sdfc::viewer
