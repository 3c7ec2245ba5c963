#include "viewer/view_tools.hpp"

#include <SDL.h>
#include <fmt/format.h>

#include <iostream>

namespace sdfc::viewer {

ViewTools::ViewTools(SceneSession& scene, LiveValues& live, CameraRig& rig, std::string device_id)
    : scene_(scene), live_(live), rig_(rig), bookmarks_(frontend::bookmarks_of(live.file())), hires_(std::move(device_id)) {}

void ViewTools::say(std::string m) {
  message_ = std::move(m);
  std::cerr << message_ << "\n";
}

bool ViewTools::key(int sym, unsigned mod, bool* moved) {
  if (mod & (KMOD_CTRL | KMOD_ALT | KMOD_GUI)) return false;
  if (int k = bookmark_key(sym)) {
    if (mod & KMOD_SHIFT) keep(k);
    else if (recall(k)) *moved = true;
    return true;
  }
  if (sym == SDLK_h) {
    start_hires();
    return true;
  }
  return false;
}

bool ViewTools::recall(int key) {
  std::optional<ir::Camera> c = bookmarks_.recall(key, scene_.module().plan.camera);
  if (!c) {
    say(fmt::format("no view kept under {} (Shift+{} keeps one)", key, key));
    return false;
  }
  rig_.reset(*c);
  say(fmt::format("view {}", key));
  return true;
}

void ViewTools::keep(int key) {
  Bookmarks next = bookmarks_;
  next.store(key, rig_.camera());
  try {
    switch (live_.save_section("bookmarks", next.yaml())) {
      case LiveValues::Saved::ChangedOnDisk:
        say(fmt::format("view {} not kept: {} changed on disk since it was loaded", key, scene_.options().path));
        return;
      case LiveValues::Saved::Written:
      case LiveValues::Saved::NothingToSave: break;
    }
  } catch (const std::exception& e) {
    say(fmt::format("view {} not kept: {}", key, e.what()));
    return;
  }
  bookmarks_ = std::move(next);
  say(fmt::format("view {} kept in {}", key, scene_.options().path));
}

void ViewTools::start_hires() {
  HiresRequest rq;
  rq.scene = scene_.options();
  rq.scene.sets = live_.overrides();
  rq.camera = with_view(scene_.module().plan.camera, rig_.camera());
  rq.width = hires_width, rq.height = hires_height, rq.samples = hires_samples;
  if (!hires_.start(std::move(rq))) return say("a hi-res render is running (its progress is in the F2 panel)");
  say(fmt::format("hi-res render of this view: {}x{}, {} sample(s)", hires_width, hires_height, hires_samples));
}

}  // namespace sdfc::viewer
