// The F1 overlay's font: lit pixels where the glyph says, a dark panel
// behind, drawn with SDL's software renderer into a plain surface.
#include <SDL.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include "viewer/overlay_text.hpp"

namespace sdfc::viewer {
namespace {

struct Canvas {
  SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, 120, 40, 32, SDL_PIXELFORMAT_RGBA32);
  SDL_Renderer* renderer = SDL_CreateSoftwareRenderer(surface);
  Canvas() {
    SDL_SetRenderDrawColor(renderer, 100, 100, 100, 255);
    SDL_RenderClear(renderer);
  }
  ~Canvas() {
    SDL_DestroyRenderer(renderer);
    SDL_FreeSurface(surface);
  }
  const Uint8* at(int x, int y) const {
    return static_cast<const Uint8*>(surface->pixels) + y * surface->pitch + x * 4;
  }
};

TEST(Overlay, DrawsGlyphPixelsOnADarkPanel) {
  Canvas c;
  ASSERT_NE(c.renderer, nullptr) << SDL_GetError();
  draw_overlay(c.renderer, {"1 fps", "7"}, 2);
  SDL_RenderPresent(c.renderer);
  // Scale 2, 4-pixel padding: '1' has its top-middle pixel lit, top-left dark.
  EXPECT_EQ(c.at(4 + 2, 4)[0], 255);
  EXPECT_LT(c.at(4, 4)[0], 100);  // the panel darkens the grey background
  // '7' on the second line (14 pixels down): the whole top row is lit.
  for (int x = 4; x < 10; ++x) EXPECT_EQ(c.at(x, 4 + 14)[0], 255) << x;
  // Outside the panel the background is untouched.
  EXPECT_EQ(c.at(110, 35)[0], 100);
  std::string path = ::testing::TempDir() + "/overlay_text.png";
  stbi_write_png(path.c_str(), c.surface->w, c.surface->h, 4, c.surface->pixels, c.surface->pitch);
}

TEST(Overlay, NoLinesDrawsNothing) {
  Canvas c;
  draw_overlay(c.renderer, {}, 2);
  SDL_RenderPresent(c.renderer);
  EXPECT_EQ(c.at(4, 4)[0], 100);
}

}  // namespace
}  // namespace sdfc::viewer
