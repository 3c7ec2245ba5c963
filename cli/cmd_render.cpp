// sdfc render SCENE -o OUT.png: compile, build on the device once, render
// one frame or a sequence (--frames) by tiles with progress on stderr, and
// write the PNG (8 or 16 bit) and any AOVs through temporary files.
#include <fmt/format.h>
#include <sdfrt/output_file.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <atomic>
#include <csignal>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>
#include <sdfrt/progress.hpp>
#include <sdfrt/renderer.hpp>

#include "cli_support.hpp"
#include "offline_render.hpp"
#include "commands.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::cli {

namespace {

std::atomic<bool> g_cancel{false};
// The first Ctrl-C stops the render cleanly (within a launch slice); a
// second one ends the process at once.
extern "C" void on_sigint(int) {
  g_cancel = true;
  std::signal(SIGINT, SIG_DFL);
}

// PoCL calls abort() when it cannot write its own kernel cache (a full disk,
// `ulimit -f`): say what probably happened, then die as before.
extern "C" void on_driver_abort(int) {
  static const char msg[] =
      "sdfc: the OpenCL driver aborted. With PoCL this usually means it could not write its kernel cache "
      "(full disk or file size limit; the cache is in $POCL_CACHE_DIR or ~/.cache/pocl)\n";
  ssize_t ignored = write(2, msg, sizeof msg - 1);
  (void)ignored;
  std::signal(SIGABRT, SIG_DFL);
  std::raise(SIGABRT);
}

struct RenderArgs {
  SceneArgs scene;
  std::string output;
  int width = 0, height = 0;
  std::string device;
  int simd_width = 0;
  int packet_rows = 0;
  int tile = 256;
  int repeat = 0;
  bool quiet = false;
  bool keep_partial = false;
  int bit_depth = 8;
  std::vector<std::string> aovs;
  std::string frames;
  double fps = 30;
  std::string kernel_file;  // a hand-edited kernel to build instead of the generated one
  bool reference = false;
  double reference_epsilon = ir::kReferenceHitEpsilon;
  int reference_samples = ir::kReferenceGrid;  // N: an N x N grid of rays per pixel
};

// --reference: ir::make_reference, plus the depth, normal and hit AOVs.
void make_reference(ir::MarchSettings& s, double eps, int grid, std::vector<std::string>& aovs) {
  ir::make_reference(s, eps, grid);
  for (const char* a : {"depth", "normal", "hit"})
    if (std::find(aovs.begin(), aovs.end(), a) == aovs.end()) aovs.push_back(a);
}

std::string read_kernel_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::invalid_argument(fmt::format("--kernel: cannot read {}", path));
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::invalid_argument(fmt::format("--kernel: {} is not a file", path));
  if (std::filesystem::file_size(path, ec) > (64u << 20))
    throw std::invalid_argument(fmt::format("--kernel: {} is larger than 64 MiB; it is no kernel", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("--kernel: cannot read {}", path));
  std::stringstream ss;
  ss << in.rdbuf();
  if (ss.str().empty()) throw std::invalid_argument(fmt::format("--kernel: {} is empty", path));
  return ss.str();
}

// The whole image lives in host memory (the device only holds one tile), so
// refuse sizes the machine cannot hold before allocating anything.
void check_host_memory(int w, int h, size_t planes) {
  const double bytes = double(w) * double(h) * double(planes) * sizeof(float);
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return;
  const double usable = 0.75 * double(pages) * double(page);
  if (bytes > usable)
    throw sdfrt::DeviceError(fmt::format("a {}x{} image with {} planes needs {:.1f} GiB of memory, more than this "
                                         "machine can give ({:.1f} GiB); render a smaller image",
                                         w, h, planes, bytes / 1073741824.0, usable / 1073741824.0));
}


int run_render(RenderArgs a) {
  // --width/--height are overrides like any other, so they are validated alike.
  if (a.width > 0) a.scene.sets.push_back(fmt::format("render.width={}", a.width));
  if (a.height > 0) a.scene.sets.push_back(fmt::format("render.height={}", a.height));
  SourceValue doc = load_scene_source(a.scene.path, a.scene.sets);
  ir::Module m = build_module(doc, a.scene.path);
  if (a.reference) make_reference(m.plan.march, a.reference_epsilon, a.reference_samples, a.aovs);

  std::signal(SIGABRT, on_driver_abort);
  sdfrt::Device device = sdfrt::open_device(a.device.empty() ? std::nullopt : std::optional<std::string>(a.device));
  bool cpu = device.info().type == sdfrt::DeviceType::Cpu;
  int width = a.simd_width > 0 ? a.simd_width : default_simd_width(cpu);
  if (m.plan.march.precision == ir::Precision::Double && !device.info().fp64)
    throw sdfrt::DeviceError(fmt::format("the scene asks for double precision, but {} has no fp64 support",
                                         device.info().device_name));
  codegen::EmitOptions eo;
  eo.simd_width = width;
  eo.packet_rows = a.packet_rows;
  eo.aovs = !a.aovs.empty();
  codegen::EmittedKernel k = codegen::emit_opencl(m, eo);
  if (!a.kernel_file.empty()) k.source = read_kernel_file(a.kernel_file);
  sdfrt::KernelSpec spec{k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""};
  // One build serves every frame: time and the camera are frame parameters.
  sdfrt::Renderer renderer(device, spec);
  const auto& bs = renderer.build_stats();
  if (!a.quiet)
    std::cerr << fmt::format("device: {}; kernel built in {:.0f} ms{}; {} pixel(s) per work-item ({}x{})\n",
                             device.info().device_name, bs.build_ms, bs.cache_hit ? " (cached)" : "", k.simd_width,
                             k.simd_width / k.packet_rows, k.packet_rows);

  const int w = m.plan.march.width, h = m.plan.march.height;
  std::signal(SIGINT, on_sigint);
  if (a.repeat > 0) {
    check_host_memory(w, h, k.planes.size());  // --repeat holds whole images in memory
    std::vector<float> frame = codegen::frame_params(m.plan, w, h, 0.0);
    sdfrt::RenderOptions opt;
    opt.tile_width = opt.tile_height = a.tile;
    opt.cancel = &g_cancel;
    // One warm-up frame, then N timed frames; the median is what to quote.
    renderer.render(frame, w, h, opt);
    std::vector<double> times;
    sdfrt::FloatImage img;
    for (int i = 0; i < a.repeat; ++i) {
      sdfrt::RenderStats st;
      img = renderer.render(frame, w, h, opt, &st);
      times.push_back(st.total_ms);
      std::cerr << fmt::format("frame {}: {:.1f} ms\n", i + 1, st.total_ms);
    }
    std::sort(times.begin(), times.end());
    double median = times.size() % 2 ? times[times.size() / 2] : 0.5 * (times[times.size() / 2 - 1] + times[times.size() / 2]);
    std::cerr << fmt::format("median {:.1f} ms over {} frames ({}x{})\n", median, a.repeat, w, h);
    sdfrt::WriteReport rep = sdfrt::write_png(a.output, img);
    if (rep.nonfinite_samples > 0)
      std::cerr << fmt::format("warning: {} NaN/Inf samples were written as black\n", rep.nonfinite_samples);
    std::cout << rep.path << "\n";
    // The AOVs of the last timed frame, so one run gives both time and error.
    for (const auto& p : write_aovs(spec, img, a.output, a.aovs)) std::cout << p << "\n";
    return kOk;
  }

  std::vector<int> frames = a.frames.empty() ? std::vector<int>{0} : parse_frames(a.frames);
  const bool sequence = !a.frames.empty();
  if (frames.back() / a.fps > expr::kMaxTime)  // animated values are checked for t in [0, kMaxTime] only
    throw std::invalid_argument(fmt::format("--frames: frame {} is at t = {:.3g} s at {} fps, past the {:g} s over which "
                                            "animated values are checked",
                                            frames.back(), frames.back() / a.fps, a.fps, expr::kMaxTime));
  if (sequence && frames.size() > 1 && !has_frame_field(a.output))
    throw std::invalid_argument(fmt::format(
        "-o '{}': {} frames need a frame-number field in the name, e.g. out/frame_%04d.png", a.output, frames.size()));
  OfflineOutput out;
  out.bit_depth = a.bit_depth;
  out.aovs = a.aovs;
  out.quiet = a.quiet;
  out.keep_partial = a.keep_partial;
  for (int fno : frames) {
    const double time = fno / a.fps;
    out.beauty = sequence && has_frame_field(a.output) ? frame_path(a.output, fno) : a.output;
    // A sequence's directory is created (out/frame_%04d.png); a single image's is not.
    auto parent = std::filesystem::path(out.beauty).parent_path();
    if (sequence && frames.size() > 1 && !parent.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(parent, ec);
      if (ec) throw sdfrt::IoError(fmt::format("cannot create '{}': {}", parent.string(), ec.message()), parent.string(), ec.value());
    }
    OfflineFrame f{codegen::frame_params(m.plan, w, h, time), w, h, m.plan.march.samples, m.plan.march.gamma};
    auto start = std::chrono::steady_clock::now();
    std::vector<std::string> paths = render_offline(renderer, f, out, a.tile, &g_cancel);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!a.quiet)
      std::cerr << fmt::format("{}rendered {}x{} in {:.0f} ms\n", sequence ? fmt::format("frame {} (t = {:.3f} s): ", fno, time) : "",
                               w, h, ms);
    for (const auto& p : paths) std::cout << p << "\n";
  }
  return kOk;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a scene to a PNG on an OpenCL device");
  auto a = std::make_shared<RenderArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("-o,--output", a->output, "Output PNG (a pattern such as out/frame_%04d.png with --frames)")->required();
  cmd->add_option("--width", a->width, "Image width (overrides render.width)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", a->height, "Image height (overrides render.height)")->check(CLI::Range(1, 16384));
  cmd->add_option("--device", a->device, "Device id from 'sdfc devices' (P:D, an index or part of the name); "
                                         "default: $SDFC_DEVICE, else the first CPU device");
  cmd->add_option("--simd-width", a->simd_width, "Pixels per work-item: 1 or 2/4/8/16 (default: 16 on CPUs, 1 on GPUs)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  cmd->add_option("--packet-rows", a->packet_rows,
                  "Pixel rows per packet, dividing --simd-width (default: 4 at width 16, i.e. 4x4 pixels; else 1)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16}));
  cmd->add_option("--tile", a->tile, "Tile size in pixels (default 256)")->check(CLI::Range(16, 16384));
  cmd->add_option("--repeat", a->repeat, "Render one warm-up and N timed frames; print each time and the median")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress or timing on stderr");
  cmd->add_flag("--keep-partial", a->keep_partial,
                "On Ctrl-C, write the tiles done so far to OUT.partial.png (the rest black; OUT.png is never "
                "written then); with render.samples > 1 it is also refreshed after each pass");
  cmd->add_option("--bit-depth", a->bit_depth, "PNG bits per channel: 8 or 16")->check(CLI::IsMember({8, 16}));
  cmd->add_option("--aov", a->aovs, "Also write these as PFM beside the image (OUT.<aov>.pfm): depth, normal, steps, iterations, material, hit")
      ->delimiter(',')
      ->check(CLI::IsMember(kAovNames));
  cmd->add_option("--frames", a->frames, "Render frames N, FIRST:LAST or FIRST:LAST:STEP at time = frame / fps; "
                                         "-o then needs a field such as %04d");
  cmd->add_option("--fps", a->fps, "Frames per second for --frames (default 30)")
      ->check(CLI::Range(0.001, 10000.0))
      ->check(finite_number());
  cmd->add_option("--kernel", a->kernel_file,
                  "Build this OpenCL file instead of the generated kernel (a hand-edited 'sdfc compile' output "
                  "for the same scene, --simd-width and --packet-rows)")
      ->each([](const std::string& p) { sdfrt::protect_input(p); });
  cmd->add_flag("--reference", a->reference,
                "Reference render of the same view: an 8x8 grid of rays per pixel (--reference-samples), double "
                "precision, hit epsilon 0.01 px, 20000 steps, step factor 0.5, bisection of every hit, central "
                "normals; writes the depth, normal and hit AOVs as pixel averages (hit = coverage) (slow)");
  cmd->add_option("--reference-epsilon", a->reference_epsilon,
                  "The reference's hit epsilon in pixel footprints (a convergence check: the reference is trusted "
                  "where a 10x smaller value changes nothing)")
      ->check(CLI::Range(1e-12, 1.0))
      ->check(finite_number());
  cmd->add_option("--reference-samples", a->reference_samples,
                  "The reference's rays per pixel: an N x N stratified grid (default 8: 64 rays; 1 = the pixel centre)")
      ->check(CLI::Range(1, 32));
  return [a] { return run_render(*a); };
}

}  // namespace sdfc::cli
