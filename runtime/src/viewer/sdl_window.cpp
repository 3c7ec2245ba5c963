#include "viewer/sdl_window.hpp"

#include "viewer/overlay_text.hpp"

#include <SDL.h>

#include <stdexcept>

namespace sdfc::viewer {

namespace {
[[noreturn]] void fail(const char* what) { throw std::runtime_error(std::string(what) + ": " + SDL_GetError()); }
}  // namespace

SdlWindow::SdlWindow(const std::string& title, int width, int height) : width_(width), height_(height) {
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) fail("cannot start SDL video (is there a display? try xvfb-run)");
  // Low-resolution frames in motion are stretched; linear filtering hides the blocks.
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, 0);
  if (!window_) {
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    fail("cannot open the window");
  }
  renderer_ = SDL_CreateRenderer(window_, -1, 0);
  if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (!renderer_) {
    SDL_DestroyWindow(window_);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    fail("cannot create an SDL renderer");
  }
  title_ = title;
}

SdlWindow::~SdlWindow() {
  if (texture_) SDL_DestroyTexture(texture_);
  SDL_DestroyRenderer(renderer_);
  SDL_DestroyWindow(window_);
  SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

void SdlWindow::show(const std::uint8_t* rgb, int w, int h, const std::vector<std::string>& overlay) {
  if (!texture_ || w != tex_w_ || h != tex_h_) {
    if (texture_) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, w, h);
    if (!texture_) fail("cannot create a texture");
    tex_w_ = w;
    tex_h_ = h;
  }
  SDL_UpdateTexture(texture_, nullptr, rgb, w * 3);
  overlay_ = overlay;
  present_again();
}

void SdlWindow::compose() {
  SDL_RenderClear(renderer_);
  if (texture_) SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
  draw_overlay(renderer_, overlay_);
  if (before_present_) before_present_();
}

void SdlWindow::present_again() {
  compose();
  SDL_RenderPresent(renderer_);
}

std::vector<std::uint8_t> SdlWindow::capture() {
  compose();  // read before the present: afterwards the back buffer is undefined
  std::vector<std::uint8_t> rgb(std::size_t(width_) * height_ * 3);
  if (SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGB24, rgb.data(), width_ * 3) != 0) fail("cannot read the window");
  SDL_RenderPresent(renderer_);
  return rgb;
}

std::string SdlWindow::driver() const {
  const char* d = SDL_GetCurrentVideoDriver();
  return d ? d : "";
}

bool SdlWindow::invisible() const {
  std::string d = driver();
  return d == "offscreen" || d == "dummy" || d == "evdev";
}

void SdlWindow::set_title(const std::string& title) {
  if (title == title_) return;
  title_ = title;
  SDL_SetWindowTitle(window_, title.c_str());
}

}  // namespace sdfc::viewer
