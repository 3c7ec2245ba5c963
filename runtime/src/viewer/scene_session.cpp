#include "viewer/scene_session.hpp"

#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <sdfrt/errors.hpp>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::viewer {

namespace {
// On a CPU the runtime launches one-packet work-groups, so any tile shape
// runs the one compiled work-group function, and the renderer's 256-pixel
// tiles (edge tiles cut to the image) are best: with uniform 128x64 tiles a
// 1280x720 frame took 113 ms, with these 103 (the host waits after every
// launch). Elsewhere the driver picks the work-group size per launch shape
// (PoCL compiles a work-group function for each), and the viewer's size
// changes with the resolution scale, so tiles of one shape mean one compile
// instead of dozens.
constexpr int kUniformTileWidth = 128, kUniformTileHeight = 64;

sdfrt::RenderOptions viewer_render_options(const sdfrt::Device& device) {
  sdfrt::RenderOptions opt;
  if (device.info().type != sdfrt::DeviceType::Cpu) {
    opt.tile_width = kUniformTileWidth;
    opt.tile_height = kUniformTileHeight;
    opt.uniform_launch = true;
  }
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

SceneSession::Built SceneSession::build(sdfrt::Device& device, const SceneOptions& options) {
  auto t0 = std::chrono::steady_clock::now();
  SourceValue doc = load_scene_source(options.path, options.sets);
  Built b;
  b.slots = mark_unlocked(doc, options.unlocks);
  auto m = std::make_unique<ir::Module>(build_module(doc, options.path));
  // With the steps plane: the F1 overlay's steps/pixel is the mean of the
  // kernel's own `steps` plane (no second march). Only that plane: with all
  // seven AOV planes a 1280x720 frame took 210 ms against 180 without.
  codegen::EmitOptions eo;
  eo.simd_width = options.simd_width;
  eo.steps_plane = true;
  codegen::EmittedKernel k = codegen::emit_opencl(*m, eo);
  sdfrt::KernelSpec spec{.source = k.source, .entry = k.entry, .simd_width = k.simd_width, .packet_rows = k.packet_rows,
                         .planes = k.planes, .scene_data = k.scene_data, .environment = k.environment};
  b.renderer = std::make_unique<sdfrt::Renderer>(device, spec);
  b.module = std::move(m);
  b.options = options;
  b.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return b;
}

void SceneSession::adopt(Built b) {
  module_ = std::move(b.module);
  renderer_ = std::move(b.renderer);
  slots_ = std::move(b.slots);
  slot_values_ = unlocked_values(slots_);
  options_ = std::move(b.options);
  last_build_ms_ = b.ms;
  ++generation_;
}

void SceneSession::compile() {
  ++builds_;
  adopt(build(*device_, options_));
}

void SceneSession::rebuild_in_background(SceneOptions next) {
  if (running_.valid()) {
    queued_ = std::move(next);
    return;
  }
  ++builds_;
  sdfrt::Device* device = device_;
  running_ = std::async(std::launch::async, [device, next = std::move(next)] { return build(*device, next); });
}

ReloadResult SceneSession::adopt_build() {
  if (!running_.valid() || running_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return ReloadResult::Unchanged;
  try {
    Built b = running_.get();
    if (queued_) {  // superseded while it built
      SceneOptions next = std::move(*queued_);
      queued_.reset();
      rebuild_in_background(std::move(next));
      return ReloadResult::Unchanged;
    }
    adopt(std::move(b));
    error_.clear();
    return ReloadResult::Reloaded;
  } catch (const std::exception& e) {
    error_ = e.what();
  }
  if (queued_) {
    SceneOptions next = std::move(*queued_);
    queued_.reset();
    rebuild_in_background(std::move(next));
  }
  return ReloadResult::Failed;
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
  frame.insert(frame.end(), slot_values_.begin(), slot_values_.end());  // the unlocked values follow the block
  return frame;
}

sdfrt::FloatImage SceneSession::render(const ir::Camera& camera, int width, int height, double time,
                                       double offset_x, double offset_y, sdfrt::RenderStats* stats) {
  return renderer_->render(frame_for(camera, width, height, time, offset_x, offset_y), width, height,
                           viewer_render_options(*device_), stats);
}

std::optional<sdfrt::FloatImage> SceneSession::render_interruptible(const ir::Camera& camera, int width, int height,
                                                                    double time, double offset_x, double offset_y,
                                                                    const std::function<bool()>& interrupt,
                                                                    sdfrt::RenderStats* stats, int pass) {
  std::atomic<bool> stop{false};
  sdfrt::RenderOptions opt = viewer_render_options(*device_);
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

sdfrt::FloatImage SceneSession::render_offline(const ir::Camera& camera, int width, int height,
                                               const std::function<void(int, int)>& progress, std::atomic<bool>* cancel) {
  sdfrt::RenderOptions opt;
  opt.progress = progress;
  opt.cancel = cancel;
  return renderer_->render(frame_for(camera, width, height, 0.0, 0, 0), width, height, opt);
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
