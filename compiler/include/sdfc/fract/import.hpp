#pragma once
// `sdfc import`: a Mandelbulber settings file as a readable sdfc scene.
#include <string>
#include <vector>

#include "sdfc/fract/fract_file.hpp"

namespace sdfc::fract {

struct Imported {
  std::string yaml;                   // the scene, each value commented with the key it came from
  std::vector<std::string> warnings;  // one line per key group that was not imported
};

// Throws SceneError at the file's line for what cannot be imported: an
// unsupported formula ("formula 'Mandelbulb' (id 2) is not supported yet"),
// a setting that would change the shape, a broken value.
Imported import_scene(const File& file);
Imported import_file(const std::string& path);

}  // namespace sdfc::fract
