#pragma once
// `bookmarks:`: views kept by `sdfc view` under the keys 1-9 (Shift+1 ...
// Shift+9 keeps one, 1 ... 9 goes back to it). Renders ignore them; the
// front end checks them like a camera, and the viewer reads them from here.
#include <vector>

#include "sdfc/frontend/value_reader.hpp"

namespace sdfc::frontend {

struct Bookmark {
  int key = 1;
  Vec3d position{0, -3, 0}, target{0, 0, 0}, up{0, 0, 1};
  double fov_degrees = 45;
};

// Reads the section's list into `out`; errors go to r's sink.
void read_bookmarks(ValueReader& r, const SourceValue& v, std::vector<Bookmark>& out);

// The bookmarks of a scene file as loaded (none without the section); a
// SceneError for a bad one.
std::vector<Bookmark> bookmarks_of(const SourceValue& doc);

}  // namespace sdfc::frontend
