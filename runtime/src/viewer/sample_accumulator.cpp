#include "viewer/sample_accumulator.hpp"

#include <algorithm>
#include <cmath>

namespace sdfc::viewer {

namespace {
double radical_inverse(int i, int base) {
  double inv = 1.0 / base, f = inv, r = 0;
  for (; i > 0; i /= base, f *= inv) r += f * (i % base);
  return r;
}
}  // namespace

std::array<double, 2> sample_offset(int index) {
  if (index <= 0) return {0.0, 0.0};
  return {radical_inverse(index, 2) - 0.5, radical_inverse(index, 3) - 0.5};
}

void SampleAccumulator::add(const sdfrt::FloatImage& image, double gamma) {
  if (image.width != width_ || image.height != height_ || samples_ == 0) {
    width_ = image.width;
    height_ = image.height;
    sum_.assign(std::size_t(width_) * height_ * 3, 0.0);
    samples_ = 0;
  }
  gamma_ = gamma;
  const std::size_t n = image.plane_size();
  for (int c = 0; c < 3; ++c) {
    auto plane = image.plane(c);
    for (std::size_t i = 0; i < n; ++i) {
      double v = plane[i];
      if (!std::isfinite(v)) v = 0;
      sum_[i * 3 + c] += std::pow(std::clamp(v, 0.0, 1.0), gamma);
    }
  }
  ++samples_;
}

std::vector<std::uint8_t> SampleAccumulator::rgb8() const {
  std::vector<std::uint8_t> out(sum_.size());
  if (samples_ == 0) return out;
  const double inv_n = 1.0 / samples_, inv_gamma = 1.0 / gamma_;
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    double v = std::pow(std::clamp(sum_[i] * inv_n, 0.0, 1.0), inv_gamma);
    out[i] = static_cast<std::uint8_t>(std::lround(v * 255.0));
  }
  return out;
}

}  // namespace sdfc::viewer
