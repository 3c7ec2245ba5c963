#pragma once
// The object-set tests' scenes: scattered spheres and boxes in three
// materials, as single shapes or smooth groups, beside other children.
#include <fmt/format.h>

#include <random>
#include <string>

#include "sdfc_test_support.hpp"

namespace sdfc::test {

inline const char* kHead =
    "camera: {position: [0, -9, 5], target: [0, 0, 1], up: [0, 0, 1], fov: 50}\n"
    "render: {width: 96, height: 64}\n"
    "lights:\n  - directional: {direction: [-0.4, 0.6, -0.7]}\n  - ambient: {intensity: 0.3}\n"
    "materials:\n  a: {color: [0.9, 0.2, 0.1]}\n  b: {color: [0.1, 0.3, 0.9], reflectivity: 0.3}\n"
    "  c: {color: [0.2, 0.8, 0.2]}\n"
    "scene:\n  union:\n";

// n scattered spheres and boxes (materials a, b, c in turn), optionally
// smooth unions of `group` of them, and `extra` lines of other children.
inline std::string scene(size_t n, size_t group = 1, const std::string& extra = "", double spread = 4, unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-spread, spread), r(0.15, 0.4);
  std::string s = kHead + extra;
  const char* mats[] = {"a", "b", "c"};
  auto shape = [&](const std::string& indent, V3 c) {
    std::string out = (rng() % 2) ? fmt::format("{}- sphere: {{radius: {:.3f}}}\n", indent, r(rng))
                                  : fmt::format("{}- box: {{size: [{:.3f}, {:.3f}, {:.3f}]}}\n", indent, 2 * r(rng),
                                                2 * r(rng), 2 * r(rng));
    return out + fmt::format("{}  translate: [{:.3f}, {:.3f}, {:.3f}]\n", indent, c[0], c[1], c[2]);
  };
  for (size_t i = 0; i < n / group; ++i) {
    V3 c{u(rng), u(rng), 1 + 0.5 * u(rng)};
    if (group == 1) {
      s += shape("    ", c) + fmt::format("      material: {}\n", mats[i % 3]);
      continue;
    }
    s += "    - smooth_union:\n        radius: 0.3\n        children:\n";
    for (size_t k = 0; k < group; ++k) s += shape("          ", {c[0] + 0.3 * k, c[1], c[2] + 0.2 * k});
    s += fmt::format("      material: {}\n", mats[i % 3]);
  }
  return s;
}

}  // namespace sdfc::test
