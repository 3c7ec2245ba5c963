#pragma once
// The SDL2 window: shows an 8-bit RGB image of any size stretched to the
// window, and owns SDL's video subsystem for its lifetime.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace sdfc::viewer {

class SdlWindow {
 public:
  // Throws std::runtime_error with SDL's message (no display, no driver).
  SdlWindow(const std::string& title, int width, int height);
  ~SdlWindow();
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  // Uploads `rgb` (w*h*3 bytes, rows top to bottom) and presents it scaled
  // to the whole window, with `overlay` lines of text on top.
  void show(const std::uint8_t* rgb, int w, int h, const std::vector<std::string>& overlay = {});
  // Shows the last image again (the panel changed, the picture did not).
  void present_again();
  // Presents again and returns what the window shows (picture, overlay and
  // panel) as 8-bit RGB rows, width() x height(): `--events`' snap.
  std::vector<std::uint8_t> capture();
  // Drawn over the picture before every present (the parameter panel).
  void set_before_present(std::function<void()> draw) { before_present_ = std::move(draw); }
  SDL_Window* sdl_window() const noexcept { return window_; }
  SDL_Renderer* sdl_renderer() const noexcept { return renderer_; }
  void set_title(const std::string& title);
  const std::string& title() const noexcept { return title_; }
  // SDL's video driver ("x11", "wayland", "offscreen", ...).
  std::string driver() const;
  // True for drivers that show nothing on a screen (offscreen, dummy).
  bool invisible() const;
  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }

 private:
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  int width_, height_;
  int tex_w_ = 0, tex_h_ = 0;
  std::string title_;
  std::vector<std::string> overlay_;
  std::function<void()> before_present_;
  void compose();
};

}  // namespace sdfc::viewer
