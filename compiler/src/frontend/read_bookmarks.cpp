// `bookmarks:` (sdfc/frontend/bookmarks.hpp), checked like a camera so a
// hand-edited one fails in `sdfc check`, not in the viewer.
#include "sdfc/frontend/bookmarks.hpp"

#include <fmt/format.h>

#include "read_camera.hpp"

namespace sdfc::frontend {

void read_bookmarks(ValueReader& r, const SourceValue& v, std::vector<Bookmark>& out) {
  if (!v.is_seq()) {
    r.sink().error(v.loc, "bookmarks: expected a list of views, e.g. '- {key: 1, position: [0, -3, 0], target: [0, 0, 0]}', got " +
                              v.kind_name(), "");
    return;
  }
  for (const auto& item : v.items) {
    MapReader m(r, item, "bookmark", {"key", "position", "target", "up", "fov"});
    if (!m.ok()) continue;
    Bookmark b;
    if (m.require("key")) b.key = m.integer("key", 1, 1, 9);
    if (m.require("position")) b.position = m.vec3("position", b.position);
    if (m.require("target")) b.target = m.vec3("target", b.target);
    b.up = m.direction("up", b.up);
    b.fov_degrees = m.number("fov", b.fov_degrees, {0, 179, true});
    const SourceValue* up = m.get("up");
    check_view(r, item.loc, up ? up->loc : item.loc, b.position, b.target, b.up, "bookmark");
    for (const auto& earlier : out)
      if (earlier.key == b.key)
        r.sink().error(item.loc, fmt::format("bookmarks: key {} is saved twice", b.key), "keep one view per key");
    out.push_back(b);
  }
}

std::vector<Bookmark> bookmarks_of(const SourceValue& doc) {
  DiagnosticSink sink;
  ValueReader r(sink);
  std::vector<Bookmark> out;
  if (const SourceValue* v = doc.is_map() ? doc.find("bookmarks") : nullptr) read_bookmarks(r, *v, out);
  sink.throw_if_any();
  return out;
}

}  // namespace sdfc::frontend
