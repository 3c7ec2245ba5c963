#pragma once
// Reading back what sdfc writes: PNG (8 or 16 bits) and Portable Float Maps.
#include <sdfrt/float_image.hpp>

#include <string>

namespace sdfrt {
// RGB planes "r", "g", "b" in [0, 1]. Throws IoError.
FloatImage read_png(const std::string& path);
// One plane ("Pf") or three ("PF"), rows stored bottom-to-top as written.
// Plane names are `name` or `name.x`, `name.y`, `name.z`. Throws IoError.
FloatImage read_pfm(const std::string& path, const std::string& name);
}  // namespace sdfrt
