#pragma once
// The importer's parts, shared between its files; not a public interface.
#include <functional>
#include <string>
#include <vector>

#include "sdfc/fract/fract_file.hpp"
#include "sdfc/fract/fract_params.hpp"
#include "formula_table.hpp"
#include "yaml_text.hpp"

namespace sdfc::fract {

// What the importer's parts share: the warnings, one line per key group sdfc
// does not import ("volumetric fog: not imported"), and the legacy
// coordinate system's mirror.
//
// With legacy_coordinate_system Mandelbulber shows the picture mirrored top
// to bottom. A camera cannot mirror, but the mapped formulas are symmetric
// under y -> -y: the scene's points, directions and the julia constant are
// reflected (world()), and the camera's up becomes -world(camera_top); its
// picture is then Mandelbulber's mirrored one.
struct ImportContext {
  std::vector<std::string> lines;
  bool mirror_y = false;
  Vec3 world(const Vec3& v) const { return mirror_y ? Vec3{v[0], -v[1], v[2]} : v; }
  void add(std::string line) {
    for (const std::string& l : lines)
      if (l == line) return;
    lines.push_back(std::move(line));
  }
};

// The camera's orthonormal frame from camera / target / camera_top.
struct CameraFrame {
  Vec3 position, target, forward, right, up;
  double distance;
};
CameraFrame camera_frame(const Params& main);  // as the file gives it
Vec3 view_target(const Params& main);          // target, or where camera_rotation looks
CameraFrame frame_of(const Vec3& position, const Vec3& target, const Vec3& top, const Params& main);
double vertical_fov_degrees(const Params& main, double version);

Node import_geometry(const File& file, const Params& main, ImportContext& w);

// One slot's part of a hybrid (hybrid_chain.cpp): its steps and its bailout.
struct HybridPart {
  ChainPart part;
  double bailout;
};
// The hybrid sequence of formula_N (1 ... 9) as one formula chain; julia
// mode adds its constant (the caller's julia field).
Node hybrid_chain(const Params& main, SourceLoc at, const std::function<HybridPart(int slot)>& part_of);
// camera:, render:, background:, lights:, materials:, effects: as YAML text.
std::string import_view(const File& file, const Params& main, const std::string& path, ImportContext& w);
std::string import_look(const File& file, const Params& main, ImportContext& w);
// The keyframes' or frames' camera path (empty when the file has none).
std::string import_camera_path(const File& file, const Params& main, ImportContext& w);

}  // namespace sdfc::fract
