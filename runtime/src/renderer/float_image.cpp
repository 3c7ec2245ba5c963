#include <sdfrt/float_image.hpp>

#include <fmt/format.h>

#include <stdexcept>

namespace sdfrt {

FloatImage::FloatImage(int w, int h, std::vector<std::string> names)
    : width(w), height(h), plane_names(std::move(names)) {
  if (w < 1 || h < 1) {
    throw std::invalid_argument(fmt::format("image size must be positive, got {}x{}", w, h));
  }
  data.assign(plane_size() * plane_names.size(), 0.0f);
}

float FloatImage::at(int k, int x, int y) const {
  if (k < 0 || k >= planes() || x < 0 || x >= width || y < 0 || y >= height) {
    throw std::out_of_range(fmt::format("FloatImage::at({}, {}, {}) outside {}x{} with {} planes",
                                        k, x, y, width, height, planes()));
  }
  return data[static_cast<std::size_t>(k) * plane_size() +
              static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(x)];
}

int FloatImage::plane_index(std::string_view name) const {
  for (std::size_t i = 0; i < plane_names.size(); ++i) {
    if (plane_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::span<const float> FloatImage::plane(int k) const {
  return std::span<const float>(data).subspan(static_cast<std::size_t>(k) * plane_size(),
                                              plane_size());
}

std::span<float> FloatImage::plane(int k) {
  return std::span<float>(data).subspan(static_cast<std::size_t>(k) * plane_size(), plane_size());
}

}  // namespace sdfrt
