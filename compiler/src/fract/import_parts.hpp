#pragma once
// The importer's parts, shared between its files; not a public interface.
#include <string>
#include <vector>

#include "sdfc/fract/fract_file.hpp"
#include "sdfc/fract/fract_params.hpp"
#include "yaml_text.hpp"

namespace sdfc::fract {

// One line per key group sdfc does not import ("volumetric fog: not imported").
struct Warnings {
  std::vector<std::string> lines;
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
CameraFrame camera_frame(const Params& main);
double vertical_fov_degrees(const Params& main, double version);

Node import_geometry(const File& file, const Params& main, Warnings& w);
// camera:, render:, background:, lights:, materials:, effects: as YAML text.
std::string import_view(const File& file, const Params& main, const std::string& path, Warnings& w);
std::string import_look(const File& file, const Params& main, Warnings& w);
// The keyframes' or frames' camera path (empty when the file has none).
std::string import_camera_path(const File& file, const Params& main, Warnings& w);

}  // namespace sdfc::fract
