#pragma once
// The interactive loop of `sdfc view`: input -> camera -> one frame of the
// scene's own kernel (sdfrt::Renderer) -> window. Small images while the
// camera moves, full resolution and then more samples when it stops.
#include <sdfrt/float_image.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viewer/camera_rig.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/live_values.hpp"
#include "viewer/param_panel.hpp"
#include "viewer/resolution_governor.hpp"
#include "viewer/sample_accumulator.hpp"
#include "viewer/scene_session.hpp"
#include "viewer/sdl_window.hpp"
#include "viewer/view_tools.hpp"

union SDL_Event;

namespace sdfc::viewer {

struct ViewerOptions {
  int width = 1280, height = 720;  // the window, and the full resolution
  int max_samples = 16;            // progressive samples per pixel when still
  double frame_budget_ms = 50;     // adaptive resolution aims below this while moving
  std::string screenshot_dir = ".";
};

// What the last step() drew.
struct FrameInfo {
  int width = 0, height = 0;  // rendered size
  int divisor = 1;            // window size / rendered size
  int samples = 0;            // accumulated samples shown (0 while moving)
  double ms = 0;              // render time
  double steps = 0;           // mean march steps per pixel (the kernel's steps plane)
  bool rendered = false;      // false when the step only waited
};

class Viewer {
 public:
  Viewer(SceneSession& scene, SdlWindow& window, ViewerOptions options);

  // Until Esc or the window is closed.
  void run();
  // F1: the stats overlay on or off (also in the window title).
  void toggle_overlay();
  bool overlay() const noexcept { return overlay_; }
  // F2: the parameter panel on or off.
  void toggle_panel();
  bool panel_shown() const noexcept { return panel_shown_; }
  LiveValues& live_values() noexcept { return live_; }
  // Bookmarks (1-9, Shift+1-9) and the hi-res render (H).
  ViewTools& tools() noexcept { return tools_; }
  // One pass of the loop: events, held keys, file poll, at most one render,
  // present. Returns false once asked to quit.
  bool step();

  // P key: renders the current camera at the window's full resolution with
  // the scene's kernel and writes a PNG (to `path`, or a fresh name in the
  // screenshot directory). Returns the path written.
  std::string screenshot(const std::string& path = {});
  // C key: the current camera as a scene-file line.
  std::string camera_yaml() const { return viewer::camera_yaml(rig_.camera()); }

  // Renders full-resolution frames one after another for `seconds` and
  // returns the frame statistics. The camera plays the scene's camera.path
  // when it has one (at its own speed, from its first key, looping), else
  // orbits the target (`orbit_degrees` in `seconds`; 0 keeps it still).
  FrameStats benchmark(double seconds, double orbit_degrees = 360);

  CameraRig& rig() noexcept { return rig_; }
  const FrameInfo& last_frame() const noexcept { return last_; }
  const std::string& last_screenshot() const noexcept { return last_screenshot_; }
  // The image last shown (interleaved 8-bit RGB, last_frame() size).
  const std::vector<std::uint8_t>& last_image() const noexcept { return shown_; }

 private:
  void handle_event(const SDL_Event& e);
  void poll_scene();
  void render_moving();
  void render_still();
  bool input_pending() const;
  void update_title();
  void show(std::vector<std::uint8_t> rgb, int w, int h);
  std::vector<std::string> overlay_lines() const;
  std::string fresh_screenshot_path() const;

  SceneSession& scene_;
  SdlWindow& window_;
  ViewerOptions opt_;
  CameraRig rig_;
  ResolutionGovernor governor_;
  SampleAccumulator samples_;
  FrameInfo last_;
  bool quit_ = false;
  bool overlay_ = false;
  bool moved_ = true;  // the camera changed since the last still frame
  double pending_yaw_ = 0, pending_pitch_ = 0;
  unsigned long long last_tick_ = 0, last_poll_tick_ = 0;
  double fps_ = 0;
  std::string last_screenshot_;
  std::vector<std::uint8_t> shown_;
  int shown_w_ = 0, shown_h_ = 0;
  LiveValues live_;
  ViewTools tools_;
  std::unique_ptr<ParamPanel> panel_;  // made on the first F2
  bool panel_shown_ = false;
};

}  // namespace sdfc::viewer
