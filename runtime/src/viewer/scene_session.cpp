#include "viewer/scene_session.hpp"

#include <sys/stat.h>

#include <atomic>
#include <sdfrt/errors.hpp>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::viewer {

namespace {
// Tiles of one shape for every image size: PoCL compiles a work-group
// function per launch shape, and the viewer's size changes with the
// resolution scale, so uniform tiles mean one compile instead of dozens.
constexpr int kTileWidth = 128, kTileHeight = 64;

sdfrt::RenderOptions viewer_render_options() {
  sdfrt::RenderOptions opt;
  opt.tile_width = kTileWidth;
  opt.tile_height = kTileHeight;
  opt.uniform_launch = true;
  return opt;
}
}  // namespace

SceneSession::SceneSession(sdfrt::Device& device, SceneOptions options)
    : device_(&device), options_(std::move(options)) {
  loaded_ = read_stamp();
  compile();
}

SceneSession::Stamp SceneSession::read_stamp() const {
  struct stat st {};
  if (::stat(options_.path.c_str(), &st) != 0) return {};
  return {static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec,
          static_cast<long long>(st.st_size), static_cast<long long>(st.st_ino)};
}

void SceneSession::compile() {
  SourceValue doc = load_scene_source(options_.path, options_.sets);
  auto m = std::make_unique<ir::Module>(build_module(doc, options_.path));
  // With the AOV planes: the F1 overlay's steps/pixel is the mean of the
  // kernel's own `steps` plane (no second march). Costs a few stores a pixel.
  codegen::EmitOptions eo;
  eo.simd_width = options_.simd_width;
  eo.aovs = true;
  codegen::EmittedKernel k = codegen::emit_opencl(*m, eo);
  sdfrt::KernelSpec spec{k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""};
  auto r = std::make_unique<sdfrt::Renderer>(*device_, spec);
  module_ = std::move(m);
  renderer_ = std::move(r);
  ++generation_;
}

ReloadResult SceneSession::poll() {
  Stamp now = read_stamp();
  if (now == loaded_) {
    has_pending_ = false;
    return ReloadResult::Unchanged;
  }
  if (now.mtime_ns < 0) return ReloadResult::Unchanged;  // mid-rename: the file is briefly absent
  if (!has_pending_ || !(now == pending_)) {
    pending_ = now;
    has_pending_ = true;
    return ReloadResult::Unchanged;
  }
  has_pending_ = false;
  loaded_ = now;
  return reload();
}

ReloadResult SceneSession::reload() {
  try {
    compile();
    error_.clear();
    return ReloadResult::Reloaded;
  } catch (const SceneError& e) {
    error_ = e.what();
  } catch (const sdfrt::DeviceError& e) {
    error_ = std::string("kernel build failed: ") + e.what();
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  return ReloadResult::Failed;
}

double SceneSession::distance_at(const ir::Vec3d& p) const { return reference::distance(*module_, p); }

std::vector<float> SceneSession::frame_for(const ir::Camera& camera, int width, int height, double time,
                                           double offset_x, double offset_y, int pass) const {
  ir::RenderPlan plan = module_->plan;
  plan.camera = camera;
  std::vector<float> frame = codegen::frame_params(plan, width, height, time);
  // the path integrator: each still pass draws the next render.samples samples, so the image converges
  if (plan.transport.integrator == ir::Transport::Integrator::Path)
    frame[abi::kFirstSample] = static_cast<float>(static_cast<long long>(pass) * plan.march.samples);
  if (offset_x != 0 || offset_y != 0) offset_frame_rays(frame, width, height, offset_x, offset_y);
  return frame;
}

sdfrt::FloatImage SceneSession::render(const ir::Camera& camera, int width, int height, double time,
                                       double offset_x, double offset_y, sdfrt::RenderStats* stats) {
  return renderer_->render(frame_for(camera, width, height, time, offset_x, offset_y), width, height,
                           viewer_render_options(), stats);
}

std::optional<sdfrt::FloatImage> SceneSession::render_interruptible(const ir::Camera& camera, int width, int height,
                                                                    double time, double offset_x, double offset_y,
                                                                    const std::function<bool()>& interrupt,
                                                                    sdfrt::RenderStats* stats, int pass) {
  std::atomic<bool> stop{false};
  sdfrt::RenderOptions opt = viewer_render_options();
  opt.cancel = &stop;
  opt.progress = [&](int, int) {
    if (interrupt()) stop = true;
  };
  try {
    return renderer_->render(frame_for(camera, width, height, time, offset_x, offset_y, pass), width, height, opt, stats);
  } catch (const sdfrt::Cancelled&) {
    return std::nullopt;
  }
}

void offset_frame_rays(std::vector<float>& frame, int width, int height, double dx, double dy) {
  // The kernel's ray is forward + right*u + up*v with u = 2x/w - 1 and
  // v = 1 - 2y/h; a shift of (dx, dy) pixels adds right*2dx/w - up*2dy/h.
  using namespace abi;
  auto get = [&](int i) { return double(frame[i]) + double(frame[i + kLowPart]); };
  for (int i = 0; i < 3; ++i) {
    double f = get(kForward + i) + get(kRight + i) * (2.0 * dx / width) - get(kUp + i) * (2.0 * dy / height);
    float hi = static_cast<float>(f);
    frame[kForward + i] = hi;
    frame[kForward + kLowPart + i] = static_cast<float>(f - double(hi));
  }
}

}  // namespace sdfc::viewer
