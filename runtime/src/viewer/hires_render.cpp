#include "viewer/hires_render.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>

namespace sdfc::viewer {

namespace fs = std::filesystem;

namespace {
fs::path candidate(const std::string& scene_path, int width, int height, int n) {
  const fs::path scene(scene_path);
  const std::string stem = scene.stem().string();
  return scene.parent_path() / (n == 1 ? fmt::format("{}-{}x{}.png", stem, width, height)
                                       : fmt::format("{}-{}x{}-{}.png", stem, width, height, n));
}
}  // namespace

std::string free_image_name(const std::string& scene_path, int width, int height) {
  int n = 1;
  while (fs::exists(candidate(scene_path, width, height, n))) ++n;
  return candidate(scene_path, width, height, n).string();
}

HiresRender::~HiresRender() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

bool HiresRender::start(HiresRequest request) {
  if (running_) return false;
  if (thread_.joinable()) thread_.join();
  running_ = true;
  cancel_ = false;
  progress_ = 0;
  say("building the kernel...");
  thread_ = std::thread([this, r = std::move(request)]() mutable { run(std::move(r)); });
  return true;
}

void HiresRender::say(std::string status, std::string written) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_ = std::move(status);
  written_ = std::move(written);
}

std::string HiresRender::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

std::string HiresRender::written() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return written_;
}

void HiresRender::run(HiresRequest rq) {
  std::string part;
  try {
    sdfrt::Device device = sdfrt::open_device(device_id_);
    rq.scene.unlocks.clear();  // every value baked: the fastest kernel for the long render
    rq.scene.sets.push_back(fmt::format("render.samples={}", rq.samples));
    SceneSession scene(device, rq.scene);
    say(fmt::format("rendering {}x{}, {} sample(s)", rq.width, rq.height, rq.samples));
    sdfrt::FloatImage img = scene.render_offline(
        rq.camera, rq.width, rq.height, [this](int done, int total) { progress_ = total > 0 ? double(done) / total : 0; },
        &cancel_);
    // Written whole under a private name, then linked to a free name: link()
    // fails on an existing file where a rename would replace it.
    part = (fs::path(rq.scene.path).parent_path() / fmt::format(".sdfc-hires-{}.part.png", ::getpid())).string();
    sdfrt::write_png(part, img);
    std::string name;
    for (int tries = 0; tries < 1000; ++tries) {
      name = free_image_name(rq.scene.path, rq.width, rq.height);
      if (::link(part.c_str(), name.c_str()) == 0) break;
      if (errno != EEXIST) throw sdfrt::IoError(fmt::format("cannot write '{}': {}", name, std::strerror(errno)), name, errno);
      name.clear();
    }
    ::unlink(part.c_str());
    if (name.empty()) throw std::runtime_error("no free file name beside the scene");
    progress_ = 1;
    say("wrote " + name, name);
  } catch (const sdfrt::Cancelled&) {
    say("hi-res render cancelled");
  } catch (const std::exception& e) {
    if (!part.empty()) ::unlink(part.c_str());
    say(std::string("hi-res render failed: ") + e.what());
  }
  running_ = false;
}

}  // namespace sdfc::viewer
