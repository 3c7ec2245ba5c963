#include "env_map_files.hpp"

#include <ImfArray.h>
#include <ImfRgbaFile.h>

#include <cmath>
#include <fstream>
#include <vector>

namespace sdfc::test {

void write_exr_map(const std::string& path, int width, int height, const MapPixel& px) {
  Imf::Array2D<Imf::Rgba> rows(height, width);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      auto c = px(x, y);
      rows[y][x] = Imf::Rgba(c[0], c[1], c[2], 1.0f);
    }
  Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_RGBA);
  file.setFrameBuffer(&rows[0][0], 1, width);
  file.writePixels(height);
}

void write_hdr_map(const std::string& path, int width, int height, const MapPixel& px) {
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      auto c = px(x, y);
      float m = std::max(c[0], std::max(c[1], c[2]));
      unsigned char rgbe[4] = {0, 0, 0, 0};
      if (m > 1e-32f) {
        int e;
        float scale = std::frexp(m, &e) * 256.0f / m;
        for (int i = 0; i < 3; ++i) rgbe[i] = static_cast<unsigned char>(c[i] * scale);
        rgbe[3] = static_cast<unsigned char>(e + 128);
      }
      out.write(reinterpret_cast<const char*>(rgbe), 4);
    }
}

}  // namespace sdfc::test
