#pragma once
// Typed reads of a .fract section with Mandelbulber 2.20's defaults: a file
// saved with "only modified parameters" holds none of the keys left at their
// default, so every key the importer reads has its default here
// (fract_defaults.cpp). A value that does not parse is a SceneError at its
// place in the file.
#include <array>
#include <string>
#include <vector>

#include "sdfc/fract/fract_file.hpp"

namespace sdfc::fract {

using Vec3 = std::array<double, 3>;

struct GradientStop {
  double at;  // 0 ... 1
  Vec3 color;
};

class Params {
 public:
  // `fractal_section`: the keys of [fractal_N] have their own defaults.
  Params(const Section& s, bool fractal_section) : s_(s), fractal_(fractal_section) {}

  bool given(const std::string& key) const { return s_.entries.count(key) != 0; }
  SourceLoc loc(const std::string& key) const;  // the key's line, or the section's

  double number(const std::string& key) const;  // `1.5` or `1,5`
  int integer(const std::string& key) const;
  bool boolean(const std::string& key) const;     // true/false (or 1/0)
  Vec3 vec3(const std::string& key) const;         // three numbers, space separated
  std::array<double, 4> vec4(const std::string& key) const;
  Vec3 colour(const std::string& key) const;       // 16-bit hex per channel, "ffff 8000 0" -> 0 ... 1
  std::vector<GradientStop> gradient(const std::string& key) const;  // "pos RRGGBB ..." (pos in 0 ... 10000)

  // The given keys that start with `prefix`, for reporting unsupported groups.
  std::vector<std::string> given_with_prefix(const std::string& prefix) const;
  const Section& section() const { return s_; }

 private:
  std::string text(const std::string& key) const;  // the value or the default
  const Section& s_;
  bool fractal_;
};

// Mandelbulber 2.20's default of a key (the text `mandelbulber2 --list`
// prints), or nullptr when the importer does not know the key. Indexed keys
// (`formula_3`, `aux_light_colour_2`) are looked up by their family.
const char* default_value(const std::string& key, bool fractal_section);

// Parses a decimal written in any locale ("0,25" or "0.25"); false if it is not one.
bool parse_number(const std::string& text, double& out);

}  // namespace sdfc::fract
