#pragma once
// What the viewer does with views besides showing them: camera bookmarks
// (1 ... 9 recalls, Shift+1 ... Shift+9 keeps the view and writes the
// scene's `bookmarks:` list) and the hi-res render (H). The keys work with
// the panel closed; the panel shows both.
#include <string>

#include "viewer/bookmarks.hpp"
#include "viewer/camera_rig.hpp"
#include "viewer/hires_render.hpp"
#include "viewer/live_values.hpp"

namespace sdfc::viewer {

class ViewTools {
 public:
  ViewTools(SceneSession& scene, LiveValues& live, CameraRig& rig, std::string device_id);

  // A key press (SDL keycode and modifiers): true when it was one of these
  // tools' keys; *moved is set when the view changed.
  bool key(int sym, unsigned mod, bool* moved);
  // The rig goes to the view kept under `key`; false when it holds none.
  bool recall(int key);
  // Keeps the current view under `key` and saves the list into the scene file.
  void keep(int key);
  // Renders the current view for a file at hires_width x hires_height.
  void start_hires();

  int hires_width = 1920, hires_height = 1080, hires_samples = 16;
  HiresRender& hires() noexcept { return hires_; }
  const Bookmarks& bookmarks() const noexcept { return bookmarks_; }
  const CameraRig& rig() const noexcept { return rig_; }
  // What the last key did ("view 3 kept in scene.yaml"), for the panel and stderr.
  const std::string& message() const noexcept { return message_; }

 private:
  void say(std::string m);

  SceneSession& scene_;
  LiveValues& live_;
  CameraRig& rig_;
  Bookmarks bookmarks_;
  HiresRender hires_;
  std::string message_;
};

}  // namespace sdfc::viewer
