// Environment map files: OpenEXR for .exr, stb_image for .hdr (Radiance
// RGBE). The size is checked from the header before any pixel is read.
#include "env_map_file.hpp"

#include <fmt/format.h>

#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <Iex.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <numbers>

// A private copy of the decoder, HDR only: its symbols stay in this file.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
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

namespace sdfc::frontend {

namespace {

void check_size(long long w, long long h) {
  if (w < 1 || h < 1) throw EnvMapError(fmt::format("the image is {} x {} pixels; it has no pixels", w, h));
  if (w > kEnvMaxWidth || h > kEnvMaxHeight || w * h > kEnvMaxPixels)
    throw EnvMapError(fmt::format("the image is {} x {} pixels; a map may be at most {} x {} and {} pixels "
                                  "(scale it down, e.g. to 2048 x 1024)", w, h, kEnvMaxWidth, kEnvMaxHeight, kEnvMaxPixels));
}

float clean(float v) { return std::isfinite(v) && v > 0 ? std::min(v, 1e6f) : 0.0f; }

EnvPixels read_exr(const std::string& path) {
  try {
    Imf::RgbaInputFile file(path.c_str());
    const Imath::Box2i dw = file.dataWindow();
    const long long w = (long long)dw.max.x - dw.min.x + 1, h = (long long)dw.max.y - dw.min.y + 1;
    check_size(w, h);
    Imf::Array2D<Imf::Rgba> rows(h, w);
    file.setFrameBuffer(&rows[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
    file.readPixels(dw.min.y, dw.max.y);
    EnvPixels px{int(w), int(h), std::vector<float>(size_t(w * h * 3))};
    for (long long y = 0; y < h; ++y)
      for (long long x = 0; x < w; ++x) {
        const Imf::Rgba& p = rows[y][x];
        float* o = &px.rgb[size_t((y * w + x) * 3)];
        o[0] = clean(p.r), o[1] = clean(p.g), o[2] = clean(p.b);
      }
    return px;
  } catch (const EnvMapError&) {
    throw;
  } catch (const std::exception& e) {
    throw EnvMapError(fmt::format("not a readable OpenEXR file ({})", e.what()));
  }
}

EnvPixels read_hdr(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  if (!stbi_info(path.c_str(), &w, &h, &channels) || !stbi_is_hdr(path.c_str()))
    throw EnvMapError(fmt::format("not a Radiance .hdr image ({})", stbi_failure_reason() ? stbi_failure_reason() : "unknown format"));
  check_size(w, h);
  std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(path.c_str(), &w, &h, &channels, 3), stbi_image_free);
  if (!data) throw EnvMapError(fmt::format("a broken .hdr image ({})", stbi_failure_reason() ? stbi_failure_reason() : "no pixels"));
  EnvPixels px{w, h, std::vector<float>(size_t(w) * h * 3)};
  for (size_t i = 0; i < px.rgb.size(); ++i) px.rgb[i] = clean(data.get()[i]);
  return px;
}

}  // namespace

EnvPixels read_env_pixels(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw EnvMapError("no such file");
  if (!fs::is_regular_file(st)) throw EnvMapError("not a regular file");
  const auto bytes = fs::file_size(path, ec);
  if (ec) throw EnvMapError(fmt::format("cannot read it ({})", ec.message()));
  if ((long long)bytes > kEnvMaxFileBytes)
    throw EnvMapError(fmt::format("the file has {} MiB; a map may have at most {} MiB", bytes >> 20, kEnvMaxFileBytes >> 20));
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".exr") return read_exr(path);
  if (ext == ".hdr") return read_hdr(path);
  throw EnvMapError("expected an equirectangular .exr or .hdr file");
}

std::vector<float> env_tables(const EnvPixels& px, double intensity, bool importance) {
  const int w = px.width, h = px.height;
  const size_t n = size_t(w) * h;
  std::vector<float> out(3 * n + (h + 1) + size_t(h) * (w + 1));
  for (size_t i = 0; i < 3 * n; ++i) out[i] = float(px.rgb[i] * intensity);
  float* marginal = &out[3 * n];
  float* rows = marginal + h + 1;
  std::vector<double> weight(n), row_sum(h, 0.0);
  double total = 0;
  for (int y = 0; y < h; ++y) {
    const double sin_theta = std::sin(std::numbers::pi * (y + 0.5) / h);
    for (int x = 0; x < w; ++x) {
      const float* c = &px.rgb[(size_t(y) * w + x) * 3];
      const double lum = importance ? 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2] : 1.0;
      weight[size_t(y) * w + x] = lum * sin_theta;
      row_sum[y] += lum * sin_theta;
    }
    total += row_sum[y];
  }
  if (!(total > 0)) return env_tables(px, intensity, false);  // black: uniform keeps the pdf defined
  double acc = 0;
  for (int y = 0; y < h; ++y) {
    marginal[y] = float(acc / total);
    acc += row_sum[y];
    float* cdf = rows + size_t(y) * (w + 1);
    double r = 0;
    for (int x = 0; x < w; ++x) {
      // a black row (never drawn) keeps a uniform CDF, so its pdf stays finite
      cdf[x] = float(row_sum[y] > 0 ? r / row_sum[y] : double(x) / w);
      r += weight[size_t(y) * w + x];
    }
    cdf[w] = 1.0f;
  }
  marginal[h] = 1.0f;
  return out;
}

}  // namespace sdfc::frontend
