#pragma once
// A rendered image: named float planes, stored plane-major.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sdfrt {

struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<std::string> plane_names;
  std::vector<float> data;  // data[k*width*height + y*width + x]

  FloatImage() = default;
  // Zero-filled image; throws std::invalid_argument on non-positive sizes.
  FloatImage(int width, int height, std::vector<std::string> plane_names);
  // Large planes are handed back for the next image when one is dropped
  // (float_image.cpp says why); copies and moves are as usual.
  FloatImage(const FloatImage&) = default;
  FloatImage(FloatImage&&) noexcept = default;
  FloatImage& operator=(const FloatImage&) = default;
  FloatImage& operator=(FloatImage&& other) noexcept;
  ~FloatImage();

  int planes() const noexcept { return static_cast<int>(plane_names.size()); }
  std::size_t plane_size() const noexcept {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  // Bounds-checked (std::out_of_range); use data/plane() in hot loops.
  float at(int plane, int x, int y) const;
  // Index of the plane with that name, or -1.
  int plane_index(std::string_view name) const;
  std::span<const float> plane(int k) const;
  std::span<float> plane(int k);
};

}  // namespace sdfrt
