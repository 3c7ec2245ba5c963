#include "renderer/launch_shape.hpp"

namespace sdfrt {
namespace {

std::size_t largest_dividing(std::size_t n, std::size_t cap) {
  for (std::size_t d = cap; d > 1; d /= 2)
    if (n % d == 0) return d;
  return 1;
}

}  // namespace

std::optional<std::array<std::size_t, 2>> launch_local_size(DeviceType type, int simd_width,
                                                            std::size_t groups_x,
                                                            std::size_t groups_y) {
  if (type != DeviceType::Cpu) return std::nullopt;
  if (simd_width > 1) return std::array<std::size_t, 2>{1, 1};
  return std::array<std::size_t, 2>{largest_dividing(groups_x, 8), largest_dividing(groups_y, 8)};
}

}  // namespace sdfrt
