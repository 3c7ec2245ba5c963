#include "viewer/viewer.hpp"

#include <SDL.h>
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <sdfrt/image_io.hpp>
#include "sdfc/codegen/camera_view.hpp"
#include <unistd.h>

namespace sdfc::viewer {

namespace {
constexpr double kMouseRadiansPerPixel = 0.003;
constexpr double kWheelSpeedStep = 1.25;
constexpr unsigned kFilePollMs = 200;

double seconds_between(unsigned long long a, unsigned long long b) {
  return double(b - a) / double(SDL_GetPerformanceFrequency());
}
std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

// Mean of the kernel's `steps` plane: march steps per pixel.
double mean_steps(const sdfrt::FloatImage& img) {
  int k = img.plane_index("steps");
  if (k < 0 || img.plane_size() == 0) return 0;
  double sum = 0;
  for (float v : img.plane(k)) sum += v;
  return sum / double(img.plane_size());
}
}  // namespace

Viewer::Viewer(SceneSession& scene, SdlWindow& window, ViewerOptions options)
    : scene_(scene), window_(window), opt_(std::move(options)), rig_(codegen::fitted(scene.module().plan.camera, opt_.width, opt_.height)),
      governor_(opt_.frame_budget_ms), live_(scene), tools_(scene, live_, rig_, scene.renderer().device().info().id) {
  last_tick_ = SDL_GetPerformanceCounter();
  update_title();
}

void Viewer::run() { while (step()) continue; }

void Viewer::toggle_panel() {
  if (!panel_) {
    panel_ = std::make_unique<ParamPanel>(window_.sdl_window(), window_.sdl_renderer(), live_, scene_, tools_);
    window_.set_before_present([this] { if (panel_shown_) panel_->draw(); });
  }
  panel_shown_ = !panel_shown_;
  window_.present_again();
}

void Viewer::handle_event(const SDL_Event& e) {
  if (panel_shown_ && panel_->handle(e)) return;
  if (e.type == SDL_KEYDOWN && !e.key.repeat && tools_.key(e.key.keysym.sym, e.key.keysym.mod, &moved_)) return;
  switch (e.type) {
    case SDL_QUIT:
      quit_ = true;
      break;
    case SDL_MOUSEMOTION:
      if (e.motion.state & (SDL_BUTTON_LMASK | SDL_BUTTON_RMASK)) {
        pending_yaw_ += e.motion.xrel * kMouseRadiansPerPixel;
        pending_pitch_ -= e.motion.yrel * kMouseRadiansPerPixel;
      }
      break;
    case SDL_MOUSEWHEEL:
      rig_.scale_speed(std::pow(kWheelSpeedStep, e.wheel.y));
      break;
    case SDL_KEYDOWN:
      if (e.key.repeat) break;
      switch (e.key.keysym.sym) {
        case SDLK_ESCAPE: quit_ = true; break;
        case SDLK_TAB: rig_.toggle_mode(); break;
        case SDLK_r:
          rig_.reset(codegen::fitted(scene_.module().plan.camera, opt_.width, opt_.height));
          moved_ = true;
          break;
        case SDLK_F1: toggle_overlay(); break;
        case SDLK_F2: toggle_panel(); break;
        case SDLK_c: std::cout << camera_yaml() << std::endl; break;
        case SDLK_p:
          try {
            std::cerr << "screenshot: " << screenshot() << "\n";
          } catch (const std::exception& ex) {
            std::cerr << "screenshot failed: " << ex.what() << "\n";
          }
          break;
        default: break;
      }
      break;
    default: break;
  }
}

void Viewer::poll_scene() {
  // Compiling blocks the loop for a moment; say why the window is frozen.
  if (scene_.change_pending()) window_.set_title(window_.title() + "  (compiling...)");
  ReloadResult r = scene_.poll();
  if (r == ReloadResult::Reloaded) {
    std::cerr << fmt::format("reloaded {} (kernel #{})\n", scene_.options().path, scene_.generation());
    moved_ = true;  // same camera, new picture: start the refinement again
  } else if (r == ReloadResult::Failed) {
    std::cerr << scene_.error() << "\n" << "keeping the last good kernel\n";
  }
}

bool Viewer::step() {
  SDL_Event e;
  while (SDL_PollEvent(&e)) handle_event(e);
  if (quit_) return false;

  unsigned long long now = SDL_GetPerformanceCounter();
  // A slow frame must not turn into a long jump.
  double dt = std::min(seconds_between(last_tick_, now), 0.25);
  last_tick_ = now;
  if (seconds_between(last_poll_tick_, now) * 1000 >= kFilePollMs) {
    last_poll_tick_ = now;
    poll_scene();
  }

  if (panel_ && panel_->take_change()) moved_ = true;  // a new value or kernel: the picture starts over
  if (panel_) panel_->idle_bake();

  const Uint8* keys = SDL_GetKeyboardState(nullptr);
  MotionInput in;
  in.forward = double(keys[SDL_SCANCODE_W]) - double(keys[SDL_SCANCODE_S]);
  in.right = double(keys[SDL_SCANCODE_D]) - double(keys[SDL_SCANCODE_A]);
  in.up = double(keys[SDL_SCANCODE_E] || keys[SDL_SCANCODE_SPACE]) -
          double(keys[SDL_SCANCODE_Q] || keys[SDL_SCANCODE_LCTRL] || keys[SDL_SCANCODE_RCTRL]);
  in.fast = keys[SDL_SCANCODE_LSHIFT] || keys[SDL_SCANCODE_RSHIFT];
  in.yaw = pending_yaw_;
  in.pitch = pending_pitch_;
  pending_yaw_ = pending_pitch_ = 0;
  bool translating = in.forward != 0 || in.right != 0 || in.up != 0;
  double de = translating ? scene_.distance_at(rig_.position()) : 0.0;
  if (rig_.apply(in, dt, de)) moved_ = true;

  if (moved_ && (translating || in.yaw != 0 || in.pitch != 0)) {
    render_moving();
  } else if (moved_ || samples_.samples() < opt_.max_samples) {
    render_still();
  } else {
    // Converged: sleep until something happens (the file is still polled).
    last_.rendered = false;
    if (SDL_WaitEventTimeout(&e, int(panel_shown_ ? 30 : kFilePollMs))) handle_event(e);
    if (panel_shown_) window_.present_again();  // the panel answers the mouse though the picture is still
  }
  update_title();
  return !quit_;
}

void Viewer::render_moving() {
  int d = governor_.divisor(opt_.width, opt_.height);
  int w = std::max(1, opt_.width / d), h = std::max(1, opt_.height / d);
  sdfrt::RenderStats st;
  sdfrt::FloatImage img = scene_.render(rig_.camera(), w, h, 0.0, 0, 0, &st);
  governor_.record(static_cast<long long>(w) * h, st.total_ms);
  std::vector<std::uint8_t> rgb = sdfrt::to_rgb8(img);
  show(std::move(rgb), w, h);
  samples_.reset();
  last_ = {w, h, d, 0, st.total_ms, mean_steps(img), true};
  fps_ = st.total_ms > 0 ? 1000.0 / st.total_ms : 0;
}

// True when the user has started to move: a still frame in progress is
// then dropped so the motion is answered at once (checked between tiles).
bool Viewer::input_pending() const {
  SDL_PumpEvents();
  if (SDL_HasEvents(SDL_KEYDOWN, SDL_KEYUP) || SDL_HasEvent(SDL_MOUSEWHEEL) || SDL_HasEvent(SDL_QUIT)) return true;
  if (SDL_GetMouseState(nullptr, nullptr) & (SDL_BUTTON_LMASK | SDL_BUTTON_RMASK))
    return SDL_HasEvent(SDL_MOUSEMOTION);
  return false;
}

void Viewer::render_still() {
  if (moved_) samples_.reset();
  auto [ox, oy] = sample_offset(samples_.samples());
  sdfrt::RenderStats st;
  std::optional<sdfrt::FloatImage> img = scene_.render_interruptible(rig_.camera(), opt_.width, opt_.height, 0.0, ox,
                                                                     oy, [this] { return input_pending(); }, &st,
                                                                     samples_.samples());
  if (!img) {
    last_.rendered = false;
    return;  // moved_ stays as it was: the next still frame starts over
  }
  moved_ = false;
  governor_.record(static_cast<long long>(opt_.width) * opt_.height, st.total_ms);
  samples_.add(*img, scene_.module().plan.march.gamma);
  // The first sample is shown as the kernel wrote it: exactly `sdfc render`.
  std::vector<std::uint8_t> rgb = samples_.samples() == 1 ? sdfrt::to_rgb8(*img) : samples_.rgb8();
  show(std::move(rgb), opt_.width, opt_.height);
  last_ = {opt_.width, opt_.height, 1, samples_.samples(), st.total_ms, mean_steps(*img), true};
  fps_ = st.total_ms > 0 ? 1000.0 / st.total_ms : 0;
}

void Viewer::show(std::vector<std::uint8_t> rgb, int w, int h) {
  shown_ = std::move(rgb);
  shown_w_ = w;
  shown_h_ = h;
  window_.show(shown_.data(), w, h, overlay_lines());
}

void Viewer::toggle_overlay() {
  overlay_ = !overlay_;
  if (!shown_.empty()) window_.show(shown_.data(), shown_w_, shown_h_, overlay_lines());  // now, not next frame
  update_title();
}

std::vector<std::string> Viewer::overlay_lines() const {
  if (!overlay_) return {};
  std::vector<std::string> lines = {
      fmt::format("{:.1f} fps  {:.1f} ms", fps_, last_.ms),
      fmt::format("{}x{}  1/{} res  {} spp", last_.width, last_.height, last_.divisor, last_.samples),
      fmt::format("{:.1f} steps/pixel", last_.steps),
      fmt::format("{}  speed x{:.3g}", rig_.mode() == CameraMode::Fly ? "fly" : "orbit", rig_.speed())};
  if (!scene_.error().empty()) lines.push_back("error: see title / stderr");
  return lines;
}

void Viewer::update_title() {
  std::string name = std::filesystem::path(scene_.options().path).filename().string();
  std::string title = fmt::format("sdfc view: {} [{}]", name, rig_.mode() == CameraMode::Fly ? "fly" : "orbit");
  if (overlay_)
    title += fmt::format("  {:.1f} fps, {:.1f} ms, {}x{} (1/{} res), {} sample(s), {:.1f} steps/pixel", fps_,
                         last_.ms, last_.width, last_.height, last_.divisor, last_.samples, last_.steps);
  if (!scene_.error().empty()) title += "  ERROR (old kernel kept): " + first_line(scene_.error());
  window_.set_title(title);
}

std::string Viewer::fresh_screenshot_path() const {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  std::string stem = std::filesystem::path(scene_.options().path).stem().string();
  std::filesystem::path dir(opt_.screenshot_dir);
  std::filesystem::path p = dir / fmt::format("sdfc-{}-{}.png", stem, stamp);
  for (int n = 2; std::filesystem::exists(p); ++n) p = dir / fmt::format("sdfc-{}-{}-{}.png", stem, stamp, n);
  return p.string();
}

std::string Viewer::screenshot(const std::string& path) {
  sdfrt::FloatImage img = scene_.render(rig_.camera(), opt_.width, opt_.height, 0.0);
  sdfrt::WriteReport rep = sdfrt::write_png(path.empty() ? fresh_screenshot_path() : path, img);
  last_screenshot_ = rep.path;
  return rep.path;
}

FrameStats Viewer::benchmark(double seconds, double orbit_degrees) {
  const ir::Camera start = rig_.camera();
  // The scene's camera (with its path) is what frame_params animates.
  const ir::Camera scene_camera = scene_.module().plan.camera;
  const bool path = !scene_camera.path.empty();
  const double path_t0 = path ? scene_camera.path.front().time : 0;
  const double path_length = path ? scene_camera.path.back().time - path_t0 : 0;
  std::cerr << (path ? fmt::format("benchmark: playing camera.path ({} keys, {:.2f} s{})\n", scene_camera.path.size(),
                                   path_length, path_length < seconds ? ", looping" : "")
                     : fmt::format("benchmark: orbiting the target by {} degrees\n", orbit_degrees));
  // Warm-up: the first launch of a shape compiles PoCL's work-group function.
  scene_.render(path ? scene_camera : start, opt_.width, opt_.height, path_t0);
  std::vector<double> frame_ms;
  const bool to_terminal = isatty(STDERR_FILENO) == 1;
  double next_line = 1.0;
  auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0;
  while (elapsed < seconds && !quit_) {
    SDL_Event e;
    while (SDL_PollEvent(&e))
      if (e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE)) quit_ = true;
    auto f0 = std::chrono::steady_clock::now();
    sdfrt::FloatImage img;
    if (path) {
      // Path time runs with the clock, as `sdfc render --frames` plays it.
      const double t = path_t0 + (path_length > 0 ? std::fmod(elapsed, path_length) : 0.0);
      img = scene_.render(scene_camera, opt_.width, opt_.height, t);
    } else {
      rig_.orbit_to(start, orbit_degrees * std::numbers::pi / 180.0 * elapsed / seconds);
      img = scene_.render(rig_.camera(), opt_.width, opt_.height, 0.0);
    }
    std::vector<std::uint8_t> rgb = sdfrt::to_rgb8(img);
    show(std::move(rgb), opt_.width, opt_.height);
    auto f1 = std::chrono::steady_clock::now();
    frame_ms.push_back(std::chrono::duration<double, std::milli>(f1 - f0).count());
    elapsed = std::chrono::duration<double>(f1 - t0).count();
    // On a terminal one line updated in place; in a log, a line every second.
    std::string status = fmt::format("benchmark: {:.1f}/{:.0f} s, {} frames", std::min(elapsed, seconds), seconds,
                                     frame_ms.size());
    if (to_terminal) std::cerr << "\r" << status << std::flush;
    else if (elapsed >= next_line || elapsed >= seconds) std::cerr << status << "\n", next_line += 1.0;
  }
  if (to_terminal) std::cerr << "\n";
  return frame_stats(std::move(frame_ms), elapsed);
}

}  // namespace sdfc::viewer
