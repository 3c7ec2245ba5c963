#include <sdfrt/image_io.hpp>

#include <sdfrt/errors.hpp>

#include "image_io/atomic_file.hpp"

#include <stb_image_write.h>

#include <fmt/format.h>

#include <climits>
#include <stdexcept>

namespace sdfrt {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  const auto* bytes = static_cast<const unsigned char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

WriteReport write_png(const std::string& path, const FloatImage& image,
                      std::array<int, 3> rgb_planes) {
  WriteReport report;
  report.path = path;
  const auto rgb = to_rgb8(image, rgb_planes, &report.nonfinite_samples);
  if (static_cast<long long>(image.width) * 3 > INT_MAX) {
    throw std::invalid_argument(fmt::format("write_png: image too wide ({})", image.width));
  }

  // Encode in memory first so every byte reaches the file through checked writes.
  std::vector<unsigned char> encoded;
  if (!stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, 3, rgb.data(),
                              image.width * 3)) {
    throw IoError(fmt::format("cannot write '{}': PNG encoding failed", path), path, 0);
  }
  AtomicFile out(path);
  out.write(encoded.data(), encoded.size());
  out.commit();
  report.bytes = encoded.size();
  return report;
}

}  // namespace sdfrt
