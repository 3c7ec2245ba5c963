#include "cli_support.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sdfrt/errors.hpp>
#include <sdfrt/output_file.hpp>

#include "sdfc/reference/at_time.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/scene_caps.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::cli {

void SceneArgs::add_to(CLI::App& cmd) {
  cmd.add_option("scene", path, "Scene file (YAML, or a Mandelbulber .fract)")->required()->each([](const std::string& p) { sdfrt::protect_input(p); });
  cmd.add_option("--set", sets, "Override a scene value by its path, e.g. --set render.width=640 "
                                "--set scene.union.0.mandelbulb.power=7 (repeatable)");
  cmd.add_flag_callback("--allow-slow", [] { scene_caps().allow_slow = true; },
                        "Accept a scene whose estimated cost per sample is over the limit (see docs/security.md)");
}

const CLI::Validator& finite_number() {
  static const CLI::Validator v(
      [](std::string& s) {
        char* end = nullptr;
        const double x = std::strtod(s.c_str(), &end);
        return std::isfinite(x) ? std::string() : "expected a finite number, got " + s;
      },
      "FINITE");
  return v;
}

void write_text_output(const std::string& path, const std::string& text) {
  if (path.empty() || path == "-") {
    std::cout << text << std::flush;
    return;
  }
  sdfrt::write_output_file(path, text);
}

// 64 lanes are four AVX-512 registers per value: a march step waits on its
// square roots and divisions, and four independent registers give the core
// other work meanwhile (the 1280x720 bench Mandelbulb: 65 ms against 105 ms
// at 16 lanes, same pixels; docs/performance.md). GPUs want one pixel per work-item.
int default_simd_width(bool device_is_cpu) { return device_is_cpu ? 64 : 1; }

void warn_if_camera_inside(const ir::Module& m, const std::string& scene_path) {
  const ir::Camera& cam = m.plan.camera;
  std::vector<ir::CameraKey> where = cam.path;
  if (where.empty()) where.push_back({0, cam.position, cam.target});
  // One evaluation on the CPU per key; a scene past --allow-slow's limit can
  // cost 1e13 operations an evaluation (nested polar_repeat): not checked.
  if (!(m.graph->node(m.root).props.cost < 1e6)) return;
  const bool animated = m.graph->animated(m.root);
  for (const ir::CameraKey& key : where) {
    const double d = reference::distance(animated ? reference::at_time(m, key.time) : m, key.position);
    if (!(d < 0)) continue;
    const std::string at = cam.loc.line > 0 ? cam.loc.str() : scene_path;
    const auto& p = key.position;
    std::cerr << printable(fmt::format(
                     "{}: warning: the camera at [{:g}, {:g}, {:g}]{} is inside a solid (the distance to its surface is "
                     "{:.3g}): every ray hits where it starts, so the image shows no shape and its normals are "
                     "unreliable (move the camera out)\n",
                     at, p[0], p[1], p[2], cam.path.empty() ? "" : fmt::format(" (path key at time {:g})", key.time), d))
              << std::flush;
    return;  // once is enough
  }
}

}  // namespace sdfc::cli
