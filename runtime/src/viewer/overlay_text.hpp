#pragma once
// The F1 overlay's text: a built-in 3x5 pixel font drawn with rectangles
// after the frame is stretched to the window, so it stays sharp at any
// resolution scale (SDL2 itself has no text).
#include <string>
#include <vector>

struct SDL_Renderer;

namespace sdfc::viewer {

// Draws `lines` from the window's top-left corner on a dark translucent
// panel, `scale` window pixels per font pixel. Lower-case letters print as
// capitals; characters without a glyph print as blanks.
void draw_overlay(SDL_Renderer* renderer, const std::vector<std::string>& lines, int scale = 2);

}  // namespace sdfc::viewer
