// sdfc render SCENE -o OUT.png: compile, build on the device, render by
// tiles with progress on stderr, write the PNG through a temporary file.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <iostream>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>
#include <sdfrt/progress.hpp>
#include <sdfrt/renderer.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::cli {

namespace {

std::atomic<bool> g_cancel{false};
extern "C" void on_sigint(int) { g_cancel = true; }

struct RenderArgs {
  SceneArgs scene;
  std::string output;
  int width = 0, height = 0;
  std::string device;
  int simd_width = 0;
  int tile = 256;
  int repeat = 0;
  bool quiet = false;
};

int run_render(RenderArgs a) {
  // --width/--height are overrides like any other, so they are validated alike.
  if (a.width > 0) a.scene.sets.push_back(fmt::format("render.width={}", a.width));
  if (a.height > 0) a.scene.sets.push_back(fmt::format("render.height={}", a.height));
  SourceValue doc = load_scene_source(a.scene.path, a.scene.sets);
  ir::Module m = build_module(doc, a.scene.path);

  sdfrt::Device device = sdfrt::open_device(a.device.empty() ? std::nullopt : std::optional<std::string>(a.device));
  bool cpu = device.info().type == sdfrt::DeviceType::Cpu;
  int width = a.simd_width > 0 ? a.simd_width : default_simd_width(cpu);
  if (m.plan.march.precision == ir::Precision::Double && !device.info().fp64)
    throw sdfrt::DeviceError(fmt::format("the scene asks for double precision, but {} has no fp64 support",
                                         device.info().device_name));
  codegen::EmittedKernel k = codegen::emit_opencl(m, {width, false});
  sdfrt::KernelSpec spec{k.source, k.entry, k.simd_width, k.planes, ""};
  sdfrt::Renderer renderer(device, spec);
  const auto& bs = renderer.build_stats();
  if (!a.quiet)
    std::cerr << fmt::format("device: {}; kernel built in {:.0f} ms{}; {} pixel(s) per work-item\n",
                             device.info().device_name, bs.build_ms, bs.cache_hit ? " (cached)" : "", k.simd_width);

  const int w = m.plan.march.width, h = m.plan.march.height;
  std::vector<float> frame = codegen::frame_params(m.plan, w, h, 0.0);
  std::signal(SIGINT, on_sigint);
  sdfrt::RenderOptions opt;
  opt.tile_width = opt.tile_height = a.tile;
  opt.cancel = &g_cancel;
  sdfrt::FloatImage img;
  if (a.repeat > 0) {
    // One warm-up frame, then N timed frames; the median is what to quote.
    renderer.render(frame, w, h, opt);
    std::vector<double> times;
    for (int i = 0; i < a.repeat; ++i) {
      sdfrt::RenderStats st;
      img = renderer.render(frame, w, h, opt, &st);
      times.push_back(st.total_ms);
      std::cerr << fmt::format("frame {}: {:.1f} ms\n", i + 1, st.total_ms);
    }
    std::sort(times.begin(), times.end());
    double median = times.size() % 2 ? times[times.size() / 2] : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
    std::cerr << fmt::format("median {:.1f} ms over {} frames ({}x{})\n", median, a.repeat, w, h);
  } else {
    sdfrt::ProgressBar bar("tiles");
    if (!a.quiet) opt.progress = bar.callback();
    sdfrt::RenderStats st;
    img = renderer.render(frame, w, h, opt, &st);
    bar.finish();
    if (!a.quiet) std::cerr << fmt::format("rendered {}x{} in {:.0f} ms\n", w, h, st.total_ms);
  }
  sdfrt::WriteReport rep = sdfrt::write_png(a.output, img);
  if (rep.nonfinite_samples > 0)
    std::cerr << fmt::format("warning: {} NaN/Inf samples were written as black\n", rep.nonfinite_samples);
  std::cout << rep.path << "\n";
  return kOk;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a scene to a PNG on an OpenCL device");
  auto a = std::make_shared<RenderArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("-o,--output", a->output, "Output PNG")->required();
  cmd->add_option("--width", a->width, "Image width (overrides render.width)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", a->height, "Image height (overrides render.height)")->check(CLI::Range(1, 16384));
  cmd->add_option("--device", a->device, "Device id from 'sdfc devices' (P:D, an index or part of the name); "
                                         "default: $SDFC_DEVICE, else the first CPU device");
  cmd->add_option("--simd-width", a->simd_width, "Pixels per work-item: 1 or 2/4/8/16 (default: 16 on CPUs, 1 on GPUs)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  cmd->add_option("--tile", a->tile, "Tile size in pixels (default 256)")->check(CLI::Range(16, 16384));
  cmd->add_option("--repeat", a->repeat, "Render one warm-up and N timed frames; print each time and the median")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress or timing on stderr");
  return [a] { return run_render(*a); };
}

}  // namespace sdfc::cli
