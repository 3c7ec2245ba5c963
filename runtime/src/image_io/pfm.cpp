#include <sdfrt/image_io.hpp>

#include "image_io/atomic_file.hpp"
#include "image_io/sample_conversion.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>

namespace sdfrt {
namespace {

// PFM sample order is fixed by the negative scale in the header.
static_assert(std::endian::native == std::endian::little,
              "write_pfm assumes a little-endian host (scale -1.0)");

// Rows bottom-to-top, samples of `count` planes interleaved per pixel.
WriteReport write_pfm_planes(const std::string& path, const FloatImage& image, const int* planes,
                             int count) {
  WriteReport report;
  report.path = path;
  const std::string header =
      fmt::format("{}\n{} {}\n-1.0\n", count == 1 ? "Pf" : "PF", image.width, image.height);

  AtomicFile out(path);
  out.write(header.data(), header.size());
  const std::size_t row_floats = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(count);
  std::vector<float> row(row_floats);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int c = 0; c < count; ++c) {
      const auto plane = image.plane(planes[c]);
      const std::size_t offset = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width);
      for (int x = 0; x < image.width; ++x) {
        row[static_cast<std::size_t>(x) * static_cast<std::size_t>(count) +
            static_cast<std::size_t>(c)] =
            finite_or_zero(plane[offset + static_cast<std::size_t>(x)], report.nonfinite_samples);
      }
    }
    out.write(row.data(), row.size() * sizeof(float));
  }
  out.commit();
  report.bytes = out.bytes_written();
  return report;
}

}  // namespace

WriteReport write_pfm(const std::string& path, const FloatImage& image, int plane) {
  require_planes(image, &plane, 1, "write_pfm");
  return write_pfm_planes(path, image, &plane, 1);
}

WriteReport write_pfm_rgb(const std::string& path, const FloatImage& image,
                          std::array<int, 3> rgb_planes) {
  require_planes(image, rgb_planes.data(), 3, "write_pfm_rgb");
  return write_pfm_planes(path, image, rgb_planes.data(), 3);
}

}  // namespace sdfrt
