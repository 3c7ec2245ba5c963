#include <sdfrt/errors.hpp>
#include <sdfrt/image_read.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <sys/stat.h>

// Private copy of the decoder: the symbols stay inside this file.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace sdfrt {

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& why, int err = 0) {
  throw IoError("cannot read " + path + ": " + why, path, err);
}
}  // namespace

FloatImage read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<stbi_us, void (*)(void*)> pixels(stbi_load_16(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!pixels) fail(path, stbi_failure_reason() ? stbi_failure_reason() : "not a PNG", errno);
  FloatImage img(w, h, {"r", "g", "b"});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        img.plane(c)[size_t(y) * w + x] = pixels.get()[(size_t(y) * w + x) * 3 + c] / 65535.0f;
  return img;
}

FloatImage read_pfm(const std::string& path, const std::string& name) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) fail(path, std::strerror(errno), errno);
  char kind[3] = {0, 0, 0};
  int w = 0, h = 0;
  float scale = 0;
  if (std::fscanf(f.get(), "%2s %d %d %f", kind, &w, &h, &scale) != 4 || kind[0] != 'P' ||
      (kind[1] != 'f' && kind[1] != 'F') || w <= 0 || h <= 0 || w > 65536 || h > 65536)
    fail(path, "not a Portable Float Map");
  std::fgetc(f.get());  // the single whitespace after the scale
  int channels = kind[1] == 'F' ? 3 : 1;
  // The sign of the scale is the byte order; 0 or NaN says neither.
  if (!(scale < 0 || scale > 0)) fail(path, "the PFM scale must be a non-zero number (its sign is the byte order)");
  bool little = scale < 0;
  // The header's size must match the data, before anything is allocated
  // (a 12 KB file may claim 65536 x 65536 pixels).
  const long data_at = std::ftell(f.get());
  struct stat st {};
  if (data_at < 0 || ::fstat(::fileno(f.get()), &st) != 0 || !S_ISREG(st.st_mode))
    fail(path, "not a regular file");
  const double need = double(w) * double(h) * channels * sizeof(float);
  if (double(st.st_size - data_at) < need)
    fail(path, "file is truncated (the header says " + std::to_string(w) + "x" + std::to_string(h) + ")");
  std::vector<float> raw(size_t(w) * h * channels);
  if (std::fread(raw.data(), sizeof(float), raw.size(), f.get()) != raw.size()) fail(path, "file is truncated");
  if (!little)
    for (float& v : raw) {
      uint32_t u;
      std::memcpy(&u, &v, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&v, &u, 4);
    }
  std::vector<std::string> names = channels == 1 ? std::vector<std::string>{name}
                                                 : std::vector<std::string>{name + ".x", name + ".y", name + ".z"};
  FloatImage img(w, h, names);
  for (int y = 0; y < h; ++y)  // PFM rows run bottom to top
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        img.plane(c)[size_t(y) * w + x] = raw[(size_t(h - 1 - y) * w + x) * channels + c];
  return img;
}

}  // namespace sdfrt
