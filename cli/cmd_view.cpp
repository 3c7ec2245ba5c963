// sdfc view SCENE: the live viewer. Opens an SDL2 window on the scene's own
// kernel, flies the camera, recompiles when the file is saved.
#include <fmt/format.h>

#include <cstdlib>
#include <iostream>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "sdfc/source/unlock.hpp"
#include "viewer/event_script.hpp"
#include "viewer/viewer.hpp"

namespace sdfc::cli {

namespace {

struct ViewArgs {
  SceneArgs scene;
  int width = 0, height = 0;
  std::string device;
  int simd_width = 0;
  int samples = 16;
  double benchmark = 0;
  double orbit_degrees = 360;
  std::string screenshot_dir = ".";
  std::vector<std::string> unlock;
  std::string events;
};

int run_view(const ViewArgs& a) {
  const std::vector<viewer::ScriptCommand> script = a.events.empty() ? std::vector<viewer::ScriptCommand>{}
                                                                     : viewer::read_event_script(a.events);
  sdfrt::Device device = sdfrt::open_device(a.device.empty() ? std::nullopt : std::optional<std::string>(a.device));
  bool cpu = device.info().type == sdfrt::DeviceType::Cpu;
  viewer::SceneOptions so{a.scene.path, a.scene.sets, a.simd_width > 0 ? a.simd_width : default_simd_width(cpu)};
  for (const auto& u : a.unlock) so.unlocks.push_back(parse_unlock(u));
  std::cerr << fmt::format("compiling {} for {}\n", a.scene.path, device.info().device_name);
  viewer::SceneSession scene(device, so);
  const auto& plan = scene.module().plan;
  if (plan.march.precision == ir::Precision::Double && !device.info().fp64)
    throw sdfrt::DeviceError(fmt::format("the scene asks for double precision, but {} has no fp64 support",
                                         device.info().device_name));

  viewer::ViewerOptions vo;
  vo.width = a.width > 0 ? a.width : plan.march.width;
  vo.height = a.height > 0 ? a.height : plan.march.height;
  vo.max_samples = a.samples;
  vo.screenshot_dir = a.screenshot_dir;
  std::optional<viewer::SdlWindow> window;
  try {
    window.emplace("sdfc view", vo.width, vo.height);
  } catch (const std::runtime_error& e) {
    throw sdfrt::DeviceError(e.what());
  }
  // Without a display SDL falls back to a driver nobody sees: fine for a
  // benchmark or when asked for by name, a silent hang otherwise.
  if (window->invisible() && a.benchmark <= 0 && !std::getenv("SDL_VIDEODRIVER"))
    throw sdfrt::DeviceError(fmt::format("no display for the window (SDL picked the '{}' driver); run under X11 or "
                                         "Wayland, or xvfb-run, or use --benchmark",
                                         window->driver()));
  viewer::Viewer v(scene, *window, vo);
  if (a.benchmark > 0) {
    viewer::FrameStats st = v.benchmark(a.benchmark, a.orbit_degrees);
    std::cout << viewer::format_frame_stats(st, vo.width, vo.height, device.info().device_name);
    return kOk;
  }
  std::cerr << "W/A/S/D move, Q/E or Space/Ctrl down/up, drag to look, wheel speed, Shift fast, Tab fly/orbit,\n"
               "P screenshot, C print camera, F1 stats in the title, F2 parameter panel, 1-9 go to a kept view,\n"
               "Shift+1-9 keep the view in the scene file, H render this view to a PNG beside the scene, R reset, Esc quit\n";
  if (!a.events.empty()) viewer::run_event_script(v, *window, scene, script);
  else v.run();
  return kOk;
}

}  // namespace

Action add_view(CLI::App& app) {
  auto* cmd = app.add_subcommand("view", "Open a live window on a scene; reloads when the file is saved");
  auto a = std::make_shared<ViewArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("--width", a->width, "Window width (default: render.width)")->check(CLI::Range(16, 16384));
  cmd->add_option("--height", a->height, "Window height (default: render.height)")->check(CLI::Range(16, 16384));
  cmd->add_option("--device", a->device, "Device id from 'sdfc devices' (P:D, an index or part of the name); "
                                         "default: $SDFC_DEVICE, else the first CPU device");
  cmd->add_option("--simd-width", a->simd_width, "Pixels per work-item: 1 or 2/4/8/16/32/64 (default: 64 on CPUs, 1 on GPUs)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_option("--samples", a->samples, "Samples per pixel to accumulate while the camera is still (default 16)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--screenshot-dir", a->screenshot_dir, "Where P saves screenshots (default: the current directory)");
  cmd->add_option("--unlock", a->unlock,
                  "PATH[=LO:HI]: the value at PATH is read per frame instead of baked (as the F2 panel does when "
                  "you touch it); with --benchmark, measures the live kernel's frame time")
      ->type_name("PATH[=LO:HI]");
  cmd->add_option("--events", a->events,
                  "Drive the window from a script of key presses, panel edits, waits and window snapshots "
                  "(one command a line: key NAME, set PATH VALUE, wait SECONDS, settle, snap FILE.png, hires W H SAMPLES, quit)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--benchmark", a->benchmark,
                  "Render at full resolution for SECONDS, playing the scene's camera.path (else orbiting the "
                  "target), print frame-time statistics and exit")
      ->check(CLI::Range(0.1, 3600.0))
      ->check(finite_number());
  cmd->add_option("--orbit-degrees", a->orbit_degrees,
                  "How far the benchmark orbit turns in its SECONDS (default 360; 0 = camera still); "
                  "scenes with a camera.path play the path instead")
      ->check(CLI::Range(-36000.0, 36000.0))
      ->check(finite_number());
  return [a] { return run_view(*a); };
}

}  // namespace sdfc::cli
