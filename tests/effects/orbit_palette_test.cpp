// Orbit-trap colour on real renders: lit by a white ambient light only, with
// the palette mixed fully, every fractal pixel shows a palette colour, so
// counting the pixels nearest each colour shows how the palette spreads.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "render_helpers.hpp"

namespace sdfc {
namespace {

using Colour = std::array<double, 3>;
const std::vector<Colour> kPalette = {{0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}, {0.1, 0.1, 0.9}};

std::string scene(const std::string& trap) {
  return "render: {width: 160, height: 90, gamma: 1}\n"
         "camera: {position: [0, -3.4, 1.2], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
         "lights:\n  - ambient: {intensity: 1}\n"
         "materials:\n  m: {orbit_trap: {" + trap + ", mix: 1}}\n"
         "scene:\n  mandelbulb: {power: 8, iterations: 8}\n  material: m\n";
}

// The share of fractal pixels nearest each palette colour.
std::vector<double> shares(const std::string& trap) {
  auto r = test::render_text(scene(trap));
  std::vector<double> count(kPalette.size(), 0);
  int hits = 0;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) {
      if (r.image.at(3, x, y) < 0) continue;
      ++hits;
      size_t best = 0;
      double best_d = 1e9;
      for (size_t k = 0; k < kPalette.size(); ++k) {
        double d = 0;
        for (int c = 0; c < 3; ++c) d += std::pow(r.image.at(c, x, y) - kPalette[k][c], 2);
        if (d < best_d) best_d = d, best = k;
      }
      count[best] += 1;
    }
  EXPECT_GT(hits, 2000);
  for (double& c : count) c /= std::max(hits, 1);
  std::printf("%s: %.2f %.2f %.2f\n", trap.c_str(), count[0], count[1], count[2]);
  return count;
}

const std::string kPaletteText = "palette: [[0.9, 0.1, 0.1], [0.1, 0.9, 0.1], [0.1, 0.1, 0.9]]";

TEST(OrbitPalette, AutomaticRangeSpreadsThePaletteOverTheSurface) {
  std::vector<double> s = shares(kPaletteText);
  for (double share : s) EXPECT_GT(share, 0.1);  // each colour covers a tenth of the fractal or more
}

TEST(OrbitPalette, OffsetCyclesRepeatAndGradientMoveIt) {
  EXPECT_GT(shares(kPaletteText + ", offset: 1")[2], 0.98);   // clamped at the last colour
  EXPECT_GT(shares(kPaletteText + ", range: [5, 6]")[0], 0.98);  // every trap below the range: the first colour
  // Repeat: the range covered twice, so both halves of the surface see every colour.
  std::vector<double> twice = shares(kPaletteText + ", cycles: 2, repeat: repeat");
  for (double share : twice) EXPECT_GT(share, 0.1);
  // A gradient whose red stop runs to 0.9 of the way: red takes most of the surface.
  std::vector<double> g = shares(
      "gradient: [{at: 0, color: [0.9, 0.1, 0.1]}, {at: 0.9, color: [0.9, 0.1, 0.1]}, {at: 1, color: [0.1, 0.1, 0.9]}]");
  EXPECT_GT(g[0], 0.7);
  EXPECT_GT(g[2], 0.0);
}

}  // namespace
}  // namespace sdfc
