// Animation: Mandelbulber's [keyframes] (frames_per_keyframe frames apart)
// or [frames] (one row per frame) become a camera path through the camera
// and target columns, at keyframe_frames_per_second (30 unless the file says).
// Other animated columns are reported, not imported.
#include <fmt/format.h>

#include <cmath>
#include <set>

#include "import_parts.hpp"

namespace sdfc::fract {
namespace {

constexpr size_t kMaxKeys = 4096;

int column(const Table& t, const std::string& name) {
  for (size_t i = 0; i < t.columns.size(); ++i)
    if (t.columns[i] == name) return int(i);
  return -1;
}

double cell(const Table& t, size_t row, int col) {
  double v;
  if (!parse_number(t.rows[row][size_t(col)], v))
    fail(t.row_locs[row], fmt::format("expected a number in column '{}', got '{}'", printable(t.columns[size_t(col)], 80),
                                      printable(t.rows[row][size_t(col)], 80)));
  return v;
}

}  // namespace

std::string import_camera_path(const File& file, const Params& main, ImportContext& w) {
  const Table& t = file.keyframes.present && !file.keyframes.rows.empty() ? file.keyframes : file.frames;
  if (t.rows.empty()) return {};
  const char* section = &t == &file.keyframes ? "keyframes" : "frames";
  static const char* kAxes[] = {"_x", "_y", "_z"};
  int cam[3], tgt[3];
  for (int k = 0; k < 3; ++k) {
    cam[k] = column(t, std::string("main_camera") + kAxes[k]);
    tgt[k] = column(t, std::string("main_target") + kAxes[k]);
  }
  bool has_cam = cam[0] >= 0 && cam[1] >= 0 && cam[2] >= 0, has_tgt = tgt[0] >= 0 && tgt[1] >= 0 && tgt[2] >= 0;
  std::set<std::string> path_columns;
  for (int k = 0; k < 3; ++k) {
    path_columns.insert(std::string("main_camera") + kAxes[k]);
    path_columns.insert(std::string("main_target") + kAxes[k]);
  }
  std::string others;
  for (const std::string& c : t.columns)
    if (c != "frame" && !path_columns.count(c)) others += (others.empty() ? "" : ", ") + c;
  if (!others.empty()) w.add(fmt::format("[{}]: the animated {} not imported (only the camera path is)", section, printable(others, 200)));
  if (!has_cam && !has_tgt) return {};
  if (t.rows.size() > kMaxKeys) fail(t.loc, fmt::format("[{}] has more than {} rows", section, kMaxKeys));

  double fps = main.given("keyframe_frames_per_second") ? main.number("keyframe_frames_per_second") : 30;
  double per_key = &t == &file.keyframes ? (main.given("frames_per_keyframe") ? main.number("frames_per_keyframe") : 100) : 1;
  if (!(fps > 0) || !(per_key > 0)) fail(t.loc, "frames per second and frames per keyframe must be positive");
  Vec3 cam_still = main.vec3("camera"), tgt_still = main.vec3("target");
  std::string o = commented("  path:", fmt::format("[{}], {} frames per second", section, num(fps)));
  o += commented("    interpolation: " + std::string(&t == &file.keyframes ? "catmull_rom" : "linear"),
                 &t == &file.keyframes ? "Mandelbulber's Akima spline, approximately" : "");
  o += "    keys:\n";
  double last_time = -1;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    double frame = cell(t, r, 0);
    double time = frame * per_key / fps;
    if (!(time > last_time)) fail(t.row_locs[r], fmt::format("[{}]: frame numbers must increase", section));
    last_time = time;
    Vec3 p = cam_still, q = tgt_still;
    for (int k = 0; k < 3; ++k) {
      if (has_cam) p[size_t(k)] = cell(t, r, cam[k]);
      if (has_tgt) q[size_t(k)] = cell(t, r, tgt[k]);
    }
    Vec3 d = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    if (std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) < 1e-6) {
      // The target sits on the camera (Mandelbulber then steers by rotation
      // columns): look the still camera's way.
      Vec3 still_dir = view_target(main);
      for (size_t k = 0; k < 3; ++k) q[k] = p[k] + still_dir[k] - cam_still[k];
      w.add(fmt::format("[{}]: a frame's target sits on its camera; it looks the still camera's way", section));
    }
    o += "      - {time: " + num(time) + ", position: " + vec(w.world(p)) + ", target: " + vec(w.world(q)) + "}\n";
  }
  return o;
}

}  // namespace sdfc::fract
