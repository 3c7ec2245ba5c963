// sdfc mesh SCENE -o OUT.stl|obj|ply: sample the scene's own distance on
// the device in a narrow band around the surface, mesh it with OpenVDB and
// write the mesh through a temporary file; one mesh per frame with --frames.
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>
#include <sdfrt/mesh/mesh_io.hpp>
#include <sdfrt/mesh/mesher.hpp>
#include <sdfrt/mesh/topology.hpp>
#include <sdfrt/progress.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "mesh_region.hpp"
#include "offline_render.hpp"
#include "sdfc/codegen/emit_mesh_kernels.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::cli {

namespace {

std::atomic<bool> g_cancel{false};
extern "C" void on_mesh_sigint(int) { g_cancel = true; }

struct MeshArgs {
  SceneArgs scene;
  std::string output;
  int resolution = 256;
  double voxel = 0;
  std::string bounds;
  double adaptivity = 0;
  double iso = std::numeric_limits<double>::quiet_NaN();
  bool colour = false;
  std::string frames;
  double fps = 30;
  bool force = false;
  double memory_limit_gib = 0;
  bool dense = false;
  bool check = false;
  std::string device;
  int simd_width = 0;
  bool quiet = false;
};

double default_memory_limit() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 8.0 * (1u << 30);
  return 0.5 * double(pages) * double(page);
}

std::string describe_bounds(const sdfrt::mesh::Mesh& m) {
  if (m.vertices.empty()) return "none";
  std::array<float, 3> lo = m.vertices[0], hi = m.vertices[0];
  for (const auto& v : m.vertices)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
  return fmt::format("{:.4g},{:.4g},{:.4g} .. {:.4g},{:.4g},{:.4g}", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

void print_check(const sdfrt::mesh::Mesh& m) {
  sdfrt::mesh::Topology t = sdfrt::mesh::check_topology(m);
  std::cerr << fmt::format("check: {}, {}; {} open, {} over-shared, {} misoriented edges; {} part(s); Euler characteristic {}\n",
                           t.watertight() ? "watertight" : "NOT watertight",
                           t.oriented() ? "consistently oriented" : "NOT consistently oriented", t.open_edges,
                           t.overshared_edges, t.misoriented_edges, t.parts, t.euler);
}

int run_mesh(const MeshArgs& a) {
  const auto format = sdfrt::mesh::format_for(a.output);
  if (!format)
    throw std::invalid_argument(fmt::format("-o '{}': a mesh file ends in .stl, .obj or .ply", a.output));
  const FrameRange frames = a.frames.empty() ? FrameRange{} : parse_frames(a.frames);
  const bool sequence = !a.frames.empty();
  if (sequence && frames.size() > 1 && !has_frame_field(a.output))
    throw std::invalid_argument(fmt::format(
        "-o '{}': {} frames need one frame-number field in the name, e.g. out/bulb_%04d.ply "
        "(write %% for a '%')", a.output, frames.size()));
  SourceValue doc = load_scene_source(a.scene.path, a.scene.sets);
  ir::Module m = build_module(doc, a.scene.path);
  const Region region = a.bounds.empty() ? scene_region(m) : parse_bounds(a.bounds);
  sdfrt::mesh::GridSpec base = make_grid(region, a.resolution, a.voxel);
  base.iso = std::isnan(a.iso) ? default_iso(m, base.voxel) : a.iso;
  if (a.colour && !sdfrt::mesh::holds_colour(*format) && !a.quiet)
    std::cerr << "sdfc: warning: STL files hold no colours; --colour is ignored (write .ply or .obj for colours)\n";

  sdfrt::Device device = sdfrt::open_device(a.device.empty() ? std::nullopt : std::optional<std::string>(a.device));
  if (m.plan.march.precision == ir::Precision::Double && !device.info().fp64)
    throw sdfrt::DeviceError(fmt::format("the scene asks for double precision, but {} has no fp64 support",
                                         device.info().device_name));
  const int width = a.simd_width > 0 ? a.simd_width : default_simd_width(device.info().type == sdfrt::DeviceType::Cpu);
  codegen::EmittedKernel k = codegen::emit_mesh_kernels(m, width);
  sdfrt::BuildStats bs;
  sdfrt::mesh::Sampler sampler(device, k.source, width, &bs, k.scene_data);
  if (!a.quiet)
    std::cerr << fmt::format("device: {}; kernel built in {:.0f} ms{}; grid {}x{}x{} voxels of {:.4g}\n",
                             device.info().device_name, bs.build_ms, bs.cache_hit ? " (cached)" : "", base.dims[0],
                             base.dims[1], base.dims[2], base.voxel);

  const double limit = a.memory_limit_gib > 0 ? a.memory_limit_gib * (1u << 30) : default_memory_limit();
  sdfrt::mesh::MesherOptions opt;
  opt.adaptivity = a.adaptivity;
  opt.colour = a.colour && sdfrt::mesh::holds_colour(*format);
  opt.gamma = m.plan.march.gamma;
  opt.dense = a.dense;
  // A fractal's distance estimate may overstate the distance: widen the band.
  opt.slack = m.graph->node(m.root).props.cls == ir::DistanceClass::Estimate ? 2.0 : 1.0;
  opt.cancel = &g_cancel;
  opt.check_memory = [&](std::size_t blocks, double bytes) {
    if (bytes > limit && !a.force)
      throw sdfrt::DeviceError(fmt::format(
          "the surface crosses {} blocks of 8x8x8 voxels, about {:.1f} GiB to mesh, more than the limit of {:.1f} GiB "
          "(--memory-limit, default half the machine's memory): use a lower --resolution, or --force",
          blocks, bytes / (1u << 30), limit / (1u << 30)));
  };
  std::signal(SIGINT, on_mesh_sigint);
  for (std::int64_t i = 0; i < frames.size(); ++i) {
    const int fno = frames.at(i);
    sdfrt::mesh::GridSpec grid = base;
    grid.time = fno / a.fps;
    const std::string path = sequence && has_frame_field(a.output) ? frame_path(a.output, fno) : a.output;
    auto parent = std::filesystem::path(path).parent_path();
    if (sequence && frames.size() > 1 && !parent.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(parent, ec);
      if (ec) throw sdfrt::IoError(fmt::format("cannot create '{}': {}", parent.string(), ec.message()), parent.string(), ec.value());
    }
    auto start = std::chrono::steady_clock::now();
    std::optional<sdfrt::ProgressBar> bar;
    if (!a.quiet) {
      bar.emplace("slabs");
      opt.progress = bar->callback();
      opt.stage = [&](const char* what) {
        bar->finish();
        std::cerr << what << " ...\n";
      };
    }
    sdfrt::mesh::MesherStats st;
    sdfrt::mesh::Mesh mesh = sdfrt::mesh::make_mesh(sampler, grid, opt, &st);
    if (bar) bar->finish();
    sdfrt::mesh::write_mesh(path, *format, mesh);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double dense = double(grid.dims[0]) * grid.dims[1] * grid.dims[2];
    if (!a.quiet) {
      std::cerr << fmt::format("{}{} triangles, {} vertices, bounds {}; volume {:.6g}, area {:.6g}; in {:.1f} s\n",
                               sequence ? fmt::format("frame {} (t = {:.3f} s): ", fno, grid.time) : "",
                               mesh.triangles.size(), mesh.vertices.size(), describe_bounds(mesh),
                               sdfrt::mesh::volume(mesh), sdfrt::mesh::area(mesh), s);
      std::cerr << fmt::format("sampled {} blocks ({} found beyond the band): {:.1f} M distances, {:.2f} % of the dense grid's {:.1f} M; level set "
                               "{:.1f} MiB\n",
                               st.blocks, st.grown, st.samples / 1e6, 100.0 * st.samples / dense, dense / 1e6,
                               st.grid_bytes / 1048576.0);
    }
    if (!a.quiet && grid.iso != 0 && std::isnan(a.iso))
      std::cerr << fmt::format("note: the surface is taken where the fractal's distance estimate is half a voxel, "
                               "{:.4g} (--iso sets it)\n", grid.iso);
    if (!a.quiet && mesh.triangles.empty() && st.unsigned_field)
      std::cerr << "note: the mesh is empty: the scene's distance is never negative in these bounds; a positive --iso "
                   "takes the surface at that distance\n";
    if (a.check) print_check(mesh);
    std::cout << path << "\n";
  }
  return kOk;
}

}  // namespace

Action add_mesh(CLI::App& app) {
  auto* cmd = app.add_subcommand("mesh", "Mesh a scene's surface for 3D printing or other tools (STL, OBJ, PLY)");
  auto a = std::make_shared<MeshArgs>();
  a->scene.add_to(*cmd);
  cmd->add_option("-o,--output", a->output, "Output mesh: .stl (binary), .obj or .ply (binary); a pattern such as "
                                            "out/bulb_%04d.ply with --frames")->required();
  auto* res = cmd->add_option("--resolution", a->resolution, "Voxels along the longest side of the bounds (default 256)")
                  ->check(CLI::Range(8, 16384));
  cmd->add_option("--voxel", a->voxel, "Voxel size in scene units, instead of --resolution")
      ->check(CLI::PositiveNumber)
      ->check(finite_number())
      ->excludes(res);
  cmd->add_option("--bounds", a->bounds, "Region to mesh, x0,y0,z0,x1,y1,z1 (default: the scene's inferred bounds); the "
                                         "solid is cut closed at its faces");
  cmd->add_option("--adaptivity", a->adaptivity, "0 keeps every polygon; up to 1 merges polygons on flat parts "
                                                 "(fewer triangles)")
      ->check(CLI::Range(0.0, 1.0))
      ->check(finite_number());
  cmd->add_option("--iso", a->iso, "Take the surface at this distance in scene units: positive thickens thin parts, "
                                   "negative thins them (default 0; half a voxel for escape-time fractals: mandelbulb, "
                                   "mandelbox, julia, hybrid)")
      ->check(finite_number());
  cmd->add_flag("--colour,--color", a->colour, "Per-vertex colour from the scene's materials and orbit traps (PLY, OBJ)");
  cmd->add_option("--frames", a->frames, "Mesh frames N, FIRST:LAST or FIRST:LAST:STEP at time = frame / fps; "
                                         "-o then needs a field such as %04d");
  cmd->add_option("--fps", a->fps, "Frames per second for --frames (default 30)")
      ->check(CLI::Range(0.001, 10000.0))
      ->check(finite_number());
  cmd->add_option("--memory-limit", a->memory_limit_gib, "Refuse a mesh whose estimated memory exceeds this many GiB "
                                                         "(default: half the machine's memory)")
      ->check(CLI::PositiveNumber)
      ->check(finite_number());
  cmd->add_flag("--force", a->force, "Mesh even when the memory estimate exceeds --memory-limit");
  cmd->add_flag("--dense", a->dense, "Sample every voxel instead of the narrow band (slow; for comparison)");
  cmd->add_flag("--check", a->check, "Check the mesh: watertight, consistently oriented, parts, Euler characteristic");
  cmd->add_option("--device", a->device, "Device id from 'sdfc devices'; default: $SDFC_DEVICE, else the first CPU device");
  cmd->add_option("--simd-width", a->simd_width, "Samples per work-item: 1 or 2/4/8/16/32/64 (default: 64 on CPUs, 1 on GPUs)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_flag("-q,--quiet", a->quiet, "No progress or summary on stderr");
  return [a] { return run_mesh(*a); };
}

}  // namespace sdfc::cli
