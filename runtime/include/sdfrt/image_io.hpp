#pragma once
// Image writers. All of them write to "<path>.tmp-XXXXXX" in the same
// directory, fsync and rename, so `path` never holds a partial image.
// Non-finite samples are written as 0 and counted.
#include <sdfrt/float_image.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sdfrt {

struct WriteReport {
  std::string path;
  long long nonfinite_samples = 0;  // NaN/Inf samples replaced by 0
  std::uint64_t bytes = 0;          // size of the written file
};

// 8-bit RGB from three planes (values already display-encoded), clamped to
// [0,1] and rounded. `nonfinite` (optional) receives the NaN/Inf count.
std::vector<std::uint8_t> to_rgb8(const FloatImage& image, std::array<int, 3> rgb_planes = {0, 1, 2},
                                  long long* nonfinite = nullptr);

// 8-bit RGB PNG. Throws IoError, or std::invalid_argument for a bad plane index.
WriteReport write_png(const std::string& path, const FloatImage& image,
                      std::array<int, 3> rgb_planes = {0, 1, 2});

// Single-channel Portable Float Map ("Pf", little-endian, rows bottom-to-top).
WriteReport write_pfm(const std::string& path, const FloatImage& image, int plane);

// Three-channel Portable Float Map ("PF").
WriteReport write_pfm_rgb(const std::string& path, const FloatImage& image,
                          std::array<int, 3> rgb_planes = {0, 1, 2});

}  // namespace sdfrt
