#include "renderer/tile_plan.hpp"

#include <sdfrt/renderer.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sdfrt {

TilePlan plan_tiles(int image_width, int image_height, int tile_width, int tile_height) {
  if (image_width < 1 || image_height < 1 || image_width > kMaxImageSide ||
      image_height > kMaxImageSide) {
    throw std::invalid_argument(fmt::format(
        "image size {}x{} is out of range: width and height must be between 1 and {}",
        image_width, image_height, kMaxImageSide));
  }
  if (tile_width < 1 || tile_height < 1) {
    throw std::invalid_argument(
        fmt::format("tile size {}x{} is invalid: both sides must be at least 1", tile_width,
                    tile_height));
  }
  TilePlan plan;
  plan.max_width = std::min(tile_width, image_width);
  plan.max_height = std::min(tile_height, image_height);
  for (int y = 0; y < image_height; y += plan.max_height) {
    for (int x = 0; x < image_width; x += plan.max_width) {
      plan.tiles.push_back({x, y, std::min(plan.max_width, image_width - x),
                            std::min(plan.max_height, image_height - y)});
    }
  }
  return plan;
}

}  // namespace sdfrt
