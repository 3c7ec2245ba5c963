#pragma once
// Progressive anti-aliasing while the camera is still: frames rendered with
// sub-pixel ray offsets are averaged in linear light (the kernel writes
// display values, gamma-encoded, which are decoded before averaging).
#include <sdfrt/float_image.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace sdfc::viewer {

// Ray offset of sample i in pixels, within [-0.5, 0.5): sample 0 is the
// pixel centre (what `sdfc render` shows), then a Halton(2, 3) sequence.
std::array<double, 2> sample_offset(int index);

class SampleAccumulator {
 public:
  void reset() { samples_ = 0; }
  // Adds one frame (planes 0..2 = r, g, b); a size change restarts.
  void add(const sdfrt::FloatImage& image, double gamma);
  int samples() const noexcept { return samples_; }
  int width() const noexcept { return width_; }
  int height() const noexcept { return height_; }
  // The average, gamma-encoded, as interleaved 8-bit RGB. NaN/Inf -> 0.
  std::vector<std::uint8_t> rgb8() const;

 private:
  int width_ = 0, height_ = 0, samples_ = 0;
  double gamma_ = 2.2;
  std::vector<double> sum_;  // linear r, g, b interleaved
};

}  // namespace sdfc::viewer
