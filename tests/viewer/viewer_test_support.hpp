#pragma once
// Shared by the viewer suites: one device per process, and stepping the real
// viewer until something happens.
#include <SDL.h>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sdfrt/device.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "viewer/viewer.hpp"

namespace sdfc::viewer::test {

inline sdfrt::Device& device() {
  static sdfrt::Device d = sdfrt::open_device();
  return d;
}

// Steps until done() (a reload, a build, a frame), or a minute and a half.
template <class Done>
bool step_until(Viewer& v, Done done) {
  auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(90)) {
    v.step();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// A key press as SDL delivers it (the viewer reads keysym.sym and .mod).
inline void key(SDL_Keycode k, Uint16 mod = KMOD_NONE) {
  SDL_Event e{};
  e.type = SDL_KEYDOWN;
  e.key.keysym.sym = k;
  e.key.keysym.mod = mod;
  e.key.state = SDL_PRESSED;
  ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError();
}

// A PNG as 8-bit RGB rows (empty when it cannot be read).
inline std::vector<std::uint8_t> read_png(const std::string& path, int& w, int& h) {
  int channels = 0;
  stbi_uc* px = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!px) return {};
  std::vector<std::uint8_t> v(px, px + std::size_t(w) * h * 3);
  stbi_image_free(px);
  return v;
}

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace sdfc::viewer::test
