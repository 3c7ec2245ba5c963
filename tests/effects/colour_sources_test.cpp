// Trap shapes and coloring sources on real renders, lit by a white ambient
// light only (so every pixel shows its albedo): each shape moves the
// palette over the fractal, the normal and position sources follow the
// geometry, the iteration source bands a fractal, and weights mix sources.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "render_helpers.hpp"

namespace sdfc {
namespace {

using Colour = std::array<double, 3>;
const std::vector<Colour> kPalette = {{0.9, 0.1, 0.1}, {0.1, 0.9, 0.1}, {0.1, 0.1, 0.9}};
const std::string kPaletteText = "palette: [[0.9, 0.1, 0.1], [0.1, 0.9, 0.1], [0.1, 0.1, 0.9]]";

std::string scene(const std::string& material, const std::string& node) {
  return "render: {width: 160, height: 90, gamma: 1}\n"
         "camera: {position: [0, -3.4, 1.2], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
         "lights:\n  - ambient: {intensity: 1}\n"
         "materials:\n  m: " + material + "\n"
         "scene:\n  " + node + "\n  material: m\n";
}

// The nearest palette colour of each pixel (-1 for a miss).
std::vector<int> palette_indices(const test::Rendered& r) {
  std::vector<int> out;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) {
      if (r.image.at(3, x, y) < 0) {
        out.push_back(-1);
        continue;
      }
      int best = 0;
      double best_d = 1e9;
      for (size_t k = 0; k < kPalette.size(); ++k) {
        double d = 0;
        for (int c = 0; c < 3; ++c) d += std::pow(r.image.at(c, x, y) - kPalette[k][c], 2);
        if (d < best_d) best_d = d, best = int(k);
      }
      out.push_back(best);
    }
  return out;
}

Colour pixel(const test::Rendered& r, test::Pixel p) { return {r.image.at(0, p.x, p.y), r.image.at(1, p.x, p.y), r.image.at(2, p.x, p.y)}; }

void expect_finite(const test::Rendered& r) {
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(r.image.at(c, x, y)));
}

TEST(TrapShapes, EachShapeSpreadsThePaletteDifferently) {
  const std::string bulb = "mandelbulb: {power: 8, iterations: 8}";
  auto cross = palette_indices(test::render_text(scene("{orbit_trap: {" + kPaletteText + ", mix: 1}}", bulb)));
  for (const char* shape : {"shape: point, point: [0, 0, 0.4]", "shape: plane, normal: [0, 0, 1], point: [0, 0, 0.2]",
                            "shape: line, direction: [0, 0, 1]", "shape: sphere, radius: 0.6"}) {
    SCOPED_TRACE(shape);
    auto r = test::render_text(scene(fmt::format("{{orbit_trap: {{{}, {}, mix: 1}}}}", kPaletteText, shape), bulb));
    expect_finite(r);
    auto idx = palette_indices(r);
    std::vector<int> count(3, 0);
    int hits = 0, changed = 0;
    for (size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] < 0) continue;
      ++hits, ++count[size_t(idx[i])];
      changed += idx[i] != cross[i];
    }
    ASSERT_GT(hits, 2000);
    fmt::print("{}: {:.2f} {:.2f} {:.2f}, {:.2f} changed\n", shape, double(count[0]) / hits, double(count[1]) / hits,
               double(count[2]) / hits, double(changed) / hits);
    // range: auto is measured over the whole surface, not only the side in view: two colours at least show widely
    int wide = 0;
    for (int c : count) wide += c > hits / 10;
    EXPECT_GE(wide, 2) << "range: auto spreads every shape's palette";
    EXPECT_GT(changed, hits / 5) << "the shape moves the colours";
  }
}

const std::string kSphere = "sphere: {radius: 1}";

TEST(ColoringSources, NormalFollowsTheSurfaceNormal) {
  auto r = test::render_text(scene("{coloring: {sources: [{normal: {palette: [[1, 0, 0], [0, 0, 1]], axis: [0, 0, 1]}}]}}", kSphere));
  expect_finite(r);
  // Towards the camera (normal -y: dot 0, half-way), the top (dot ~1: blue) and below (mostly red).
  Colour top = pixel(r, test::project(r.module.plan, {0, -0.2, 0.97}));
  Colour mid = pixel(r, test::project(r.module.plan, {0, -1, 0}));
  Colour bottom = pixel(r, test::project(r.module.plan, {0, -0.8, -0.6}));
  EXPECT_GT(top[2], 0.9);
  EXPECT_LT(top[0], 0.1);
  EXPECT_NEAR(mid[0], 0.5, 0.1);
  EXPECT_NEAR(mid[2], 0.5, 0.1);
  EXPECT_NEAR(bottom[0], 0.8, 0.1);  // dot -0.6: a fifth of the way to blue
  EXPECT_NEAR(bottom[2], 0.2, 0.1);
}

TEST(ColoringSources, PositionFollowsTheHeight) {
  // range auto: the sphere's extent along the axis, [-1, 1].
  auto r = test::render_text(scene("{coloring: {sources: [{position: {palette: [[1, 0, 0], [0, 0, 1]]}}]}}", kSphere));
  expect_finite(r);
  Colour high = pixel(r, test::project(r.module.plan, {0, -0.6, 0.8}));
  Colour low = pixel(r, test::project(r.module.plan, {0, -0.8, -0.6}));
  EXPECT_NEAR(high[2], 0.9, 0.05);  // z = 0.8: nine tenths of the way to blue
  EXPECT_NEAR(low[0], 0.8, 0.05);   // z = -0.6: a fifth
}

TEST(ColoringSources, WeightsAndMixBlendTheSources) {
  auto r = test::render_text(scene(
      "{color: [0, 1, 0], coloring: {mix: 0.5, sources: [{normal: {palette: [[1, 0, 0], [1, 0, 0]]}, weight: 0.7},"
      " {position: {palette: [[0, 0, 1], [0, 0, 1]]}, weight: 0.3}]}}",
      kSphere));
  Colour c = pixel(r, test::project(r.module.plan, {0, -1, 0}));
  EXPECT_NEAR(c[0], 0.35, 0.01);  // half the 0.7 red
  EXPECT_NEAR(c[1], 0.5, 0.01);   // half the material's green
  EXPECT_NEAR(c[2], 0.15, 0.01);  // half the 0.3 blue
}

// The smooth iteration count through a mirrored palette: bands across a
// Juliabulb, more of them with more cycles.
TEST(ColoringSources, IterationBandsAFractal) {
  auto changes = [](int cycles) {
    auto r = test::render_text(scene(fmt::format("{{coloring: {{sources: [{{iteration: {{{}, cycles: {}, repeat: mirror}}}}]}}}}",
                                                 kPaletteText, cycles),
                                     "mandelbulb: {power: 8, iterations: 10, bailout: 2, julia: [0.35, -0.3, 0.2]}"));
    expect_finite(r);
    auto idx = palette_indices(r);
    int n = 0;
    for (int y = 0; y < r.image.height; ++y)
      for (int x = 1; x < r.image.width; ++x) {
        int a = idx[size_t(y * r.image.width + x - 1)], b = idx[size_t(y * r.image.width + x)];
        n += a >= 0 && b >= 0 && a != b;
      }
    fmt::print("iteration, cycles {}: {} colour changes along rows\n", cycles, n);
    return n;
  };
  int one = changes(1), four = changes(4);
  EXPECT_GT(four, 100) << "the count varies over the surface";
  EXPECT_GT(four, 2 * one) << "more cycles, more bands";
}

}  // namespace
}  // namespace sdfc
