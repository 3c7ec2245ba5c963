#pragma once
// The scene the viewer shows: compiled module + built Renderer, and the file
// it came from. poll() notices saves and swaps in a new kernel; a save that
// does not compile (scene or build error) keeps the last good kernel.
#include <sdfrt/device.hpp>
#include <sdfrt/float_image.hpp>
#include <sdfrt/renderer.hpp>

#include <atomic>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sdfc/ir/module.hpp"
#include "sdfc/source/unlock.hpp"

namespace sdfc::viewer {

struct SceneOptions {
  std::string path;
  std::vector<std::string> sets;  // --set overrides, reapplied on every reload
  int simd_width = 64;
  std::vector<UnlockRequest> unlocks = {};  // values the kernel reads per frame (the panel's live values)
};

enum class ReloadResult { Unchanged, Reloaded, Failed };

class SceneSession {
 public:
  // Compiles and builds the scene once; a SceneError or BuildError here
  // propagates (there is no previous kernel to fall back on).
  SceneSession(sdfrt::Device& device, SceneOptions options);

  // Checks the file's stamp (mtime, size, inode). A change is acted on once
  // the stamp has been seen unchanged on one more poll, so an editor's
  // truncate-then-write is not compiled half-written.
  ReloadResult poll();
  // True when the next poll() will recompile if the file stays as it is.
  bool change_pending() const noexcept { return has_pending_; }
  // Recompiles now, whatever the stamp says.
  ReloadResult reload();

  const ir::Module& module() const noexcept { return *module_; }
  sdfrt::Renderer& renderer() noexcept { return *renderer_; }
  // Successful compiles so far (1 after construction).
  int generation() const noexcept { return generation_; }
  // The message of the last failed reload; empty after a success.
  const std::string& error() const noexcept { return error_; }
  const SceneOptions& options() const noexcept { return options_; }

  // Builds the scene with `next` options in a background thread while the
  // current kernel keeps drawing; a build asked for while one runs waits and
  // replaces it (the first one's result is dropped).
  void rebuild_in_background(SceneOptions next);
  bool building() const noexcept { return running_.valid(); }
  // Swaps in a finished background build (Reloaded), or keeps the current
  // kernel when it failed (Failed, error() says why); Unchanged while none is done.
  ReloadResult adopt_build();
  // Kernel builds so far, in the foreground or background, successful or not.
  int builds() const noexcept { return builds_; }
  double last_build_ms() const noexcept { return last_build_ms_; }
  // The current kernel's unlocked values and what each is now.
  const UnlockSlots& slots() const noexcept { return slots_; }
  void set_slot(int index, double value) { slot_values_.at(size_t(index)) = static_cast<float>(value); }
  // The file was written by the viewer itself: no reload for it.
  void note_own_save() { loaded_ = read_stamp(); has_pending_ = false; }

  // The scene distance at p, from the CPU reference evaluator (speed scaling).
  double distance_at(const ir::Vec3d& p) const;

  // Renders the scene from `camera` at width x height. The optional offset
  // (in pixels, within +-0.5) shifts every ray for progressive
  // anti-aliasing; {0, 0} is exactly what `sdfc render` computes.
  sdfrt::FloatImage render(const ir::Camera& camera, int width, int height, double time,
                           double offset_x = 0, double offset_y = 0, sdfrt::RenderStats* stats = nullptr);
  // The same, but `interrupt` is asked between tiles (pass: the still
  // frame's index, which the path integrator turns into fresh samples); when it returns true
  // the frame is abandoned and nullopt returned.
  std::optional<sdfrt::FloatImage> render_interruptible(const ir::Camera& camera, int width, int height,
                                                        double time, double offset_x, double offset_y,
                                                        const std::function<bool()>& interrupt,
                                                        sdfrt::RenderStats* stats = nullptr, int pass = 0);
  // A picture for a file (the hi-res key): progress(done, total) per tile;
  // `cancel` is checked before every launch (then sdfrt::Cancelled is thrown).
  sdfrt::FloatImage render_offline(const ir::Camera& camera, int width, int height,
                                   const std::function<void(int, int)>& progress, std::atomic<bool>* cancel);

 private:
  struct Stamp {
    long long mtime_ns = -1, size = -1, inode = -1;
    bool operator==(const Stamp&) const = default;
  };
  Stamp read_stamp() const;
  struct Built {
    std::unique_ptr<ir::Module> module;
    std::unique_ptr<sdfrt::Renderer> renderer;
    UnlockSlots slots;
    SceneOptions options;
    double ms = 0;
  };
  static Built build(sdfrt::Device& device, const SceneOptions& options);  // throws
  void adopt(Built b);
  void compile();  // throws; replaces module_/renderer_ only on success
  std::vector<float> frame_for(const ir::Camera& camera, int width, int height, double time, double offset_x,
                               double offset_y, int pass = 0) const;

  sdfrt::Device* device_;
  SceneOptions options_;
  std::unique_ptr<ir::Module> module_;
  std::unique_ptr<sdfrt::Renderer> renderer_;
  Stamp loaded_, pending_;
  bool has_pending_ = false;
  int generation_ = 0;
  std::string error_;
  UnlockSlots slots_;
  std::vector<float> slot_values_;
  std::future<Built> running_;
  std::optional<SceneOptions> queued_;
  int builds_ = 0;
  double last_build_ms_ = 0;
};

// Shifts the rays of a frame block (codegen::frame_params layout) by
// (dx, dy) pixels of a width x height image: the image plane moves, the
// camera position does not.
void offset_frame_rays(std::vector<float>& frame, int width, int height, double dx, double dy);

}  // namespace sdfc::viewer
