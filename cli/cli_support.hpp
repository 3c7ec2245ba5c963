#pragma once
// Pieces several subcommands share.
#include <string>
#include <vector>

#include "sdfc/ir/module.hpp"

namespace CLI {
class App;
class Validator;
}

namespace sdfc::cli {

// Options every scene command takes: the file and --set overrides.
struct SceneArgs {
  std::string path;
  std::vector<std::string> sets;
  void add_to(CLI::App& cmd);
};

// A CLI11 check that refuses NaN and infinities (CLI::Range lets NaN through).
const CLI::Validator& finite_number();

// Writes text to `path` through a temporary file and a rename ("-" = stdout).
void write_text_output(const std::string& path, const std::string& text);

// A camera inside a solid sees only the solid's inside: every ray hits where
// it starts, and the normals there come from a finite difference close to
// float resolution (about 10 degrees off). Prints a warning to stderr, with
// the camera's position and line, for the camera and for every key of its path.
void warn_if_camera_inside(const ir::Module& m, const std::string& scene_path);

// The SIMD width to emit for a device: packets on CPUs, one pixel on GPUs.
int default_simd_width(bool device_is_cpu);

}  // namespace sdfc::cli
