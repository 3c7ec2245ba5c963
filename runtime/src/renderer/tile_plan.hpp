#pragma once
// Internal: how an image is cut into tiles (row-major, clamped at the edges).
#include <vector>

namespace sdfrt {

struct Tile {
  int x0 = 0, y0 = 0, width = 0, height = 0;
};

struct TilePlan {
  std::vector<Tile> tiles;
  int max_width = 0;   // largest tile: sizes the reusable device buffer
  int max_height = 0;
};

// Throws std::invalid_argument for image sides outside [1, kMaxImageSide]
// or tile sides < 1.
TilePlan plan_tiles(int image_width, int image_height, int tile_width, int tile_height);

}  // namespace sdfrt
