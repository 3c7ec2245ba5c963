#pragma once
// The hi-res key (H): the current view rendered again for a file, at a size
// and sample count chosen in the panel, on its own device queue in a
// background thread while the window keeps drawing. The picture is a PNG
// next to the scene ("<scene>-<W>x<H>.png", "-2", "-3" ... when taken); it
// appears under its name only when complete and never replaces a file.
#include <atomic>
#include <mutex>
#include <string>
#include <thread>

#include "sdfc/ir/render_plan.hpp"
#include "viewer/scene_session.hpp"

namespace sdfc::viewer {

struct HiresRequest {
  SceneOptions scene;  // the file, the --set overrides (the panel's edits) and the SIMD width
  ir::Camera camera;
  int width = 1920, height = 1080, samples = 16;
};

class HiresRender {
 public:
  // `device_id`: the viewer's device ("P:D"), opened again for a queue of its own.
  explicit HiresRender(std::string device_id) : device_id_(std::move(device_id)) {}
  ~HiresRender();  // cancels a running render and waits for it
  HiresRender(const HiresRender&) = delete;
  HiresRender& operator=(const HiresRender&) = delete;

  // Starts a render; false (nothing started) while one runs.
  bool start(HiresRequest request);
  bool running() const noexcept { return running_; }
  void cancel() noexcept { cancel_ = true; }
  double progress() const noexcept { return progress_; }  // 0 ... 1 of the tiles
  // "building the kernel...", "rendering 1920x1080, 16 samples", "wrote PATH" or "failed: why".
  std::string status() const;
  // The file the last finished render wrote (empty before one, or after a failure).
  std::string written() const;

 private:
  void run(HiresRequest request);
  void say(std::string status, std::string written = {});

  std::string device_id_;
  std::thread thread_;
  std::atomic<bool> running_{false}, cancel_{false};
  std::atomic<double> progress_{0};
  mutable std::mutex mutex_;
  std::string status_, written_;
};

// `dir/stem-WxH.png`, or the first of "-2", "-3", ... that does not exist yet.
std::string free_image_name(const std::string& scene_path, int width, int height);

}  // namespace sdfc::viewer
