#pragma once
// Internal: shared checks and sample sanitising of the image writers.
#include <sdfrt/float_image.hpp>

#include <array>
#include <cmath>
#include <cstdint>

namespace sdfrt {

// Throws std::invalid_argument for an empty image or a plane index out of range.
void require_planes(const FloatImage& image, const int* planes, int count, const char* writer);

// NaN/Inf -> 0, counted.
inline float finite_or_zero(float value, long long& nonfinite) {
  if (std::isfinite(value)) return value;
  ++nonfinite;
  return 0.0f;
}

// Clamp to [0,1] and round to the nearest 8-bit code.
inline std::uint8_t to_u8(float value) {
  const float clamped = value < 0.0f ? 0.0f : (value > 1.0f ? 1.0f : value);
  return static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
}

}  // namespace sdfrt
