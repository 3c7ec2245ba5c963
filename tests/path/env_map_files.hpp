#pragma once
// Writes environment maps for the tests: OpenEXR (half RGBA, as most maps
// are) and Radiance .hdr (flat RGBE scanlines), from a function of the pixel.
#include <array>
#include <functional>
#include <string>

namespace sdfc::test {

using MapPixel = std::function<std::array<float, 3>(int x, int y)>;
void write_exr_map(const std::string& path, int width, int height, const MapPixel& px);
void write_hdr_map(const std::string& path, int width, int height, const MapPixel& px);

}  // namespace sdfc::test
