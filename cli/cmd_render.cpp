// sdfc render SCENE -o OUT: compile, build on the device once, render one
// frame or a sequence (--frames) by tiles with progress on stderr, and write
// the image (PNG, EXR, PFM, JPEG) or video (MP4, MKV, WebM) the name asks
// for, and any AOVs, through temporary files.
#include <fmt/format.h>
#include <sdfrt/output_file.hpp>

#include <algorithm>
#include <chrono>
#include <climits>
#include <filesystem>
#include <atomic>
#include <csignal>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <unistd.h>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>
#include <sdfrt/progress.hpp>
#include <sdfrt/renderer.hpp>

#include "cli_support.hpp"
#include "farm_render.hpp"
#include "offline_render.hpp"
#include "render_repeat.hpp"
#include "commands.hpp"
#include "output_format.hpp"
#include "video_output.hpp"
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
  int samples = 0;  // --samples: overrides render.samples
  bool verbose = false, fit = false;
  std::string device;
  int simd_width = 0;
  int packet_rows = 0;
  int tile = 256, repeat = 0;
  bool quiet = false, keep_partial = false;
  int bit_depth = 0;  // the format's default
  std::string format;
  int quality = -1;
  bool alpha = false;
  std::string number_from = "first";
  std::vector<std::string> aovs;
  std::string frames;
  double fps = 30;
  std::string kernel_file;  // a hand-edited kernel to build instead of the generated one
  bool reference = false;
  double reference_epsilon = ir::kReferenceHitEpsilon;
  int reference_samples = ir::kReferenceGrid;  // N: an N x N grid of rays per pixel
  FarmArgs farm;  // --shard, --region, --parts (cli/farm_args.cpp)
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

int run_render(RenderArgs a) {
  // --width/--height are overrides like any other, so they are validated alike.
  if (a.width > 0) a.scene.sets.push_back(fmt::format("render.width={}", a.width));
  if (a.height > 0) a.scene.sets.push_back(fmt::format("render.height={}", a.height));
  if (a.samples > 0) a.scene.sets.push_back(fmt::format("render.samples={}", a.samples));
  if (a.fit) a.scene.sets.push_back("camera.fit=true");
  SourceValue doc = load_scene_source(a.scene.path, a.scene.sets);
  ir::Module m = build_module(doc, a.scene.path);
  warn_if_camera_inside(m, a.scene.path);
  if (a.reference) make_reference(m.plan.march, a.reference_epsilon, a.reference_samples, a.aovs);
  // The output's kind and its options are checked before the kernel builds.
  // A part of a still (--region, --parts) is a region file of display values, merged into a PNG.
  const Format format = a.farm.splits_still() ? Format::Png : output_format(a.output, a.format);
  const OutputChoices choices =
      resolve_choices(format, {a.bit_depth, a.quality, a.alpha || m.plan.march.alpha}, !a.aovs.empty());
  if (a.farm.splits_still() && choices.alpha)
    throw std::invalid_argument("a region file carries no alpha: render the still whole for --alpha");
  if (is_video(format) && !a.farm.shard.empty())
    throw std::invalid_argument("--shard splits a frame sequence or a still's parts, not a video: render image frames");
  if (a.repeat > 0 && format != Format::Png) throw std::invalid_argument("--repeat writes a PNG: name the output .png");
  // A range, never a list: --frames 0:2147483647 costs no memory; refused before the build.
  const FrameRange frames = a.frames.empty() ? FrameRange{} : parse_frames(a.frames);
  if (is_video(format) && (m.plan.march.width % 2 || m.plan.march.height % 2))
    throw std::invalid_argument(fmt::format("a video needs an even width and height (yuv420p), not {}x{}",
                                            m.plan.march.width, m.plan.march.height));

  if (std::find(a.aovs.begin(), a.aovs.end(), "albedo") != a.aovs.end() &&
      m.plan.transport.integrator != ir::Transport::Integrator::Path)
    throw std::invalid_argument("--aov albedo is written by the path integrator; add render.integrator: path to the scene "
                                "(or --set render.integrator=path)");
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
  eo.aovs = !a.aovs.empty() || choices.alpha;  // alpha is the hit plane
  eo.alpha = choices.alpha;
  eo.linear = format == Format::Exr;
  codegen::EmittedKernel k = codegen::emit_opencl(m, eo);
  if (!a.kernel_file.empty()) k.source = read_kernel_file(a.kernel_file);
  sdfrt::KernelSpec spec{.source = k.source, .entry = k.entry, .simd_width = k.simd_width, .packet_rows = k.packet_rows,
                         .planes = k.planes, .scene_data = k.scene_data, .environment = k.environment};
  // One build serves every frame: time and the camera are frame parameters.
  sdfrt::Renderer renderer(device, spec);
  const auto& bs = renderer.build_stats();
  if (a.verbose)
    std::cerr << fmt::format("device: {}; kernel built in {:.0f} ms{}; {} pixel(s) per work-item ({}x{})\n",
                             device.info().device_name, bs.build_ms, bs.cache_hit ? " (cached)" : "", k.simd_width,
                             k.simd_width / k.packet_rows, k.packet_rows);
  else if (!a.quiet)
    std::cerr << fmt::format("rendering on {} (kernel {})\n", device.info().device_name,
                             bs.cache_hit ? "built earlier, from the cache" : fmt::format("built in {:.1f} s", bs.build_ms / 1000));

  const int w = m.plan.march.width, h = m.plan.march.height;
  std::signal(SIGINT, on_sigint);
  std::signal(SIGTERM, on_sigint);  // a farm's scheduler stops a task so: temp files go, no partial image
  if (a.repeat > 0) return render_repeated({&renderer, &m.plan, a.tile, a.repeat, a.output, a.aovs, &g_cancel});

  const bool sequence = !a.frames.empty();
  const bool video = is_video(format);
  check_sequence_output(frames, sequence, a.fps, a.number_from, a.output, video);
  OfflineOutput out;
  out.format = format;
  out.bit_depth = choices.bit_depth;
  out.quality = choices.quality;
  out.alpha = choices.alpha;
  out.aovs = a.aovs;
  out.quiet = a.quiet || video;  // a video shows frames done, not tiles
  out.keep_partial = a.keep_partial;
  if (a.farm.splits_still()) return render_still_parts({&renderer, &m.plan, w, h, a.tile, out, a.output, &g_cancel}, a.farm);
  std::optional<VideoOutput> vid;
  if (video) {
    const int total = static_cast<int>(std::min<std::int64_t>(frames.size(), INT_MAX));  // for the progress line
    vid.emplace(a.output, format, w, h, a.fps, choices.quality, total, a.quiet);
    out.video = vid->writer();
  }
  const IndexSlice mine = a.farm.task_slice(frames.size(), sequence);
  for (std::int64_t i = mine.begin; i < mine.end; i += mine.stride) {  // i: the frame's place in --frames
    const int fno = frames.at(i);
    const double time = fno / a.fps;
    out.beauty = sequence && has_frame_field(a.output) ? frame_path(a.output, sequence_number(frames, i, a.number_from))
                                                       : a.output;
    if (a.farm.skip_done_frame(out, fno)) continue;
    // A sequence's directory is created (out/frame_%04d.png); a single image's is not.
    auto parent = std::filesystem::path(out.beauty).parent_path();
    if (sequence && frames.size() > 1 && !parent.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(parent, ec);
      if (ec) throw sdfrt::IoError(fmt::format("cannot create '{}': {}", parent.string(), ec.message()), parent.string(), ec.value());
    }
    OfflineFrame f{codegen::frame_params(m.plan, w, h, time), w, h, m.plan.march.samples, m.plan.march.gamma};
    auto start = std::chrono::steady_clock::now();
    std::vector<std::string> paths;
    try {
      paths = render_offline(renderer, f, out, a.tile, &g_cancel);
    } catch (const sdfrt::Cancelled&) {
      if (vid) vid->stopped(a.keep_partial);
      throw;
    }
    if (vid) {
      vid->frame_done();
      continue;
    }
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!a.quiet)
      std::cerr << fmt::format("{}rendered {}x{} in {:.0f} ms\n", sequence ? fmt::format("frame {} (t = {:.3f} s): ", fno, time) : "",
                               w, h, ms);
    for (const auto& p : paths) std::cout << p << "\n";
  }
  if (vid) std::cout << vid->finish() << "\n";
  return kOk;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a scene to an image or a video on an OpenCL device");
  auto a = std::make_shared<RenderArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("-o,--output", a->output,
                  "Output file; its extension picks the format: .png, .exr, .pfm, .jpg, or with --frames a video "
                  ".mp4, .mkv, .webm, or an image pattern such as out/frame_%04d.png")
      ->required();
  cmd->add_option("--format", a->format, "Write this format whatever the extension: png, exr, pfm, jpg, mp4, mkv, webm")
      ->check(CLI::IsMember(format_names()));
  cmd->add_flag("--alpha", a->alpha,
                "Coverage as alpha, the background left out (as render.alpha: true): straight alpha in PNG, "
                "premultiplied in EXR");
  cmd->add_option("--quality", a->quality,
                  "JPEG quality 1-100 (default 90); for video the CRF, lower is better (H.264 0-51, default 18; "
                  "VP9 0-63, default 32)")
      ->check(CLI::Range(0, 100));
  cmd->add_option("--number-from", a->number_from,
                  "Sequence file numbers: 'first' (default) counts output frames up from FIRST of --frames, '0' from 0; "
                  "either way without gaps when STEP > 1")
      ->check(CLI::IsMember({"0", "first"}));
  cmd->add_option("--width", a->width, "Image width (overrides render.width)")->check(CLI::Range(1, 16384));
  cmd->add_option("--height", a->height, "Image height (overrides render.height)")->check(CLI::Range(1, 16384));
  cmd->add_option("--samples", a->samples, "Samples per pixel (overrides render.samples)")->check(CLI::Range(1, 1024));
  cmd->add_flag("--fit", a->fit, "Place the camera so the scene fills the frame, looking the way it looks (as camera.fit: true)");
  cmd->add_flag("--verbose", a->verbose, "Also print the kernel's build time and its packet shape (pixels per work-item)");
  cmd->add_option("--device", a->device, "Device id from 'sdfc devices' (P:D, an index or part of the name); "
                                         "default: $SDFC_DEVICE, else the first CPU device");
  cmd->add_option("--simd-width", a->simd_width, "Pixels per work-item: 1 or 2/4/8/16/32/64 (default: 64 on CPUs, 1 on GPUs)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_option("--packet-rows", a->packet_rows,
                  "Pixel rows per packet, dividing --simd-width (default: 4 at widths 16 and 32, 8 at 64, i.e. 4x4, 8x4 and 8x8 pixels; else 1)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_option("--tile", a->tile, "Tile size in pixels (default 256)")->check(CLI::Range(16, 16384));
  cmd->add_option("--repeat", a->repeat, "Render one warm-up and N timed frames; print each time and the median")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress or timing on stderr");
  cmd->add_flag("--keep-partial", a->keep_partial,
                "On Ctrl-C, write the tiles done so far to OUT.partial.png (or .exr; the rest black; OUT is never "
                "written then), or a video's finished frames to OUT.partial.mp4; with render.samples > 1 the "
                "image is also refreshed after each pass");
  cmd->add_option("--bit-depth", a->bit_depth, "Bits per channel: PNG 8 (default) or 16; EXR 16 (half, default) or 32 (float)")
      ->check(CLI::IsMember({8, 16, 32}));
  cmd->add_option("--aov", a->aovs, "Also write these: as channels of an EXR (Z, N.X/N.Y/N.Z, steps, iterations, material, hit, "
                                    "albedo.R/G/B), else as PFM beside the image (OUT.<aov>.pfm): depth, normal, steps, iterations, "
                                    "material, hit, albedo (the path integrator's first-hit colour, for denoisers)")
      ->delimiter(',')
      ->check(CLI::IsMember(kAovNames));
  cmd->add_option("--frames", a->frames, "Render frames N, FIRST:LAST or FIRST:LAST:STEP at time = frame / fps; "
                                         "-o then needs a field such as %04d (%% for a '%')");
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
  a->farm.add_to(*cmd);
  return [a] { return run_render(*a); };
}

}  // namespace sdfc::cli
