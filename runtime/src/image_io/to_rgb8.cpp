#include <sdfrt/image_io.hpp>

#include "image_io/sample_conversion.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace sdfrt {

void require_planes(const FloatImage& image, const int* planes, int count, const char* writer) {
  if (image.width < 1 || image.height < 1 ||
      image.data.size() != image.plane_size() * static_cast<std::size_t>(image.planes())) {
    throw std::invalid_argument(fmt::format("{}: image is empty or its data size does not match "
                                            "{}x{} with {} planes",
                                            writer, image.width, image.height, image.planes()));
  }
  for (int i = 0; i < count; ++i) {
    if (planes[i] < 0 || planes[i] >= image.planes()) {
      throw std::invalid_argument(fmt::format("{}: plane index {} out of range (image has {} planes)",
                                              writer, planes[i], image.planes()));
    }
  }
}

std::vector<std::uint8_t> to_rgb8(const FloatImage& image, std::array<int, 3> rgb_planes,
                                  long long* nonfinite) {
  require_planes(image, rgb_planes.data(), 3, "to_rgb8");
  const std::size_t pixels = image.plane_size();
  std::vector<std::uint8_t> rgb(pixels * 3);
  long long bad = 0;
  for (int c = 0; c < 3; ++c) {
    const auto plane = image.plane(rgb_planes[static_cast<std::size_t>(c)]);
    for (std::size_t i = 0; i < pixels; ++i) {
      rgb[i * 3 + static_cast<std::size_t>(c)] = to_u8(finite_or_zero(plane[i], bad));
    }
  }
  if (nonfinite) *nonfinite = bad;
  return rgb;
}

}  // namespace sdfrt
