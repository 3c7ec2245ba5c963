// Materials across a smooth union, rendered: two differently
// coloured spheres, smoothly united and lit by ambient light only (so a
// pixel's colour is its albedo), show a mix at the seam and their own pure
// colours on their far sides; an orbit-trap fractal keeps its palette
// colours when it is smoothly united with another material.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "e2e_support.hpp"

namespace sdfc::e2e {
namespace {

using Rgb = std::array<double, 3>;

Rgb pixel(const sdfrt::FloatImage& img, int x, int y) { return {img.at(0, x, y), img.at(1, x, y), img.at(2, x, y)}; }
double diff(const Rgb& a, const Rgb& b) {
  return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
}
Rgb encode(const Rgb& c, double gamma) {
  return {std::pow(c[0], 1 / gamma), std::pow(c[1], 1 / gamma), std::pow(c[2], 1 / gamma)};
}

class SmoothUnionColours : public ::testing::TestWithParam<int> {};

TEST_P(SmoothUnionColours, SeamIsAMixFarSidesArePure) {
  constexpr int W = 160, H = 80;
  const Rgb red{0.9, 0.1, 0.1}, blue{0.1, 0.2, 0.9};
  ir::Module m = test::compile_text(fmt::format(
      "camera: {{position: [0, -4, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}}\n"
      "render: {{width: {}, height: {}}}\n"
      "lights: [{{ambient: {{color: [1, 1, 1], intensity: 1}}}}]\n"
      "materials: {{red: {{color: [{}, {}, {}]}}, blue: {{color: [{}, {}, {}]}}}}\n"
      "scene:\n"
      "  smooth_union:\n"
      "    radius: 0.5\n"
      "    children:\n"
      "      - {{sphere: {{radius: 0.8}}, translate: [-0.7, 0, 0], material: red}}\n"
      "      - {{sphere: {{radius: 0.8}}, translate: [0.7, 0, 0], material: blue}}\n",
      W, H, red[0], red[1], red[2], blue[0], blue[1], blue[2]));
  sdfrt::FloatImage img = render(m, GetParam());
  const double gamma = m.plan.march.gamma;
  const Rgb pure_red = encode(red, gamma), pure_blue = encode(blue, gamma);
  const Rgb half = encode({0.5 * (red[0] + blue[0]), 0.5 * (red[1] + blue[1]), 0.5 * (red[2] + blue[2])}, gamma);
  for (int y : {H / 2 - 1, H / 2, H / 2 + 6}) {
    SCOPED_TRACE(fmt::format("row {}", y));
    int first = -1, last = -1;
    for (int x = 0; x < W; ++x)
      if (img.at(3, x, y) >= 0) {
        if (first < 0) first = x;
        last = x;
      }
    ASSERT_GT(last - first, W / 2) << "the spheres should span the row";
    // The far sides: the outer fifth of each sphere's span is one material.
    int span = last - first + 1;
    for (int x = first; x < first + span / 10; ++x) EXPECT_LT(diff(pixel(img, x, y), pure_red), 2e-3) << x;
    for (int x = last - span / 10 + 1; x <= last; ++x) EXPECT_LT(diff(pixel(img, x, y), pure_blue), 2e-3) << x;
    // The seam, at x = 0 in the world, between the two centre columns:
    // half and half, far from either colour.
    for (int x : {W / 2 - 1, W / 2}) {
      Rgb c = pixel(img, x, y);
      EXPECT_LT(diff(c, half), 0.03) << x;
      EXPECT_GT(diff(c, pure_red), 0.15) << x;
      EXPECT_GT(diff(c, pure_blue), 0.15) << x;
    }
    // Across the seam the colour runs from red to blue: the red channel
    // never rises from left to right.
    for (int x = first + 1; x <= last; ++x) EXPECT_LE(img.at(0, x, y), img.at(0, x - 1, y) + 1e-4) << x;
  }
}

INSTANTIATE_TEST_SUITE_P(Widths, SmoothUnionColours, ::testing::Values(1, 8),
                         [](const auto& info) { return "w" + std::to_string(info.param); });

// A Mandelbulb with an orbit-trap palette, smoothly united with a sphere of
// another material: wherever the blend leaves the surface as the hard union
// has it (the same depth), the colour is the hard union's, palette included.
// A small sphere behind the camera puts the camera inside the scene's bounds,
// so both marches start at the eye and take the same steps wherever the
// blend does not change the distance.
TEST(SmoothUnionColours, OrbitTrapPaletteSurvivesTheBlend) {
  const std::string kids =
      "{mandelbulb: {power: 8, iterations: 8}, material: bulb}, "
      "{sphere: {radius: 0.5}, translate: [1.5, 0, 0], material: ball}";
  auto scene = [&](bool smooth, bool trap) {
    return test::compile_text(fmt::format(
        "camera: {{position: [0.6, -3.2, 0.4], target: [0.6, 0, 0], up: [0, 0, 1], fov: 45}}\n"
        "render: {{width: 96, height: 64}}\n"
        "materials:\n"
        "  bulb: {{color: [0.6, 0.6, 0.6]{}}}\n"
        "  ball: {{color: [0.1, 0.3, 0.9]}}\n"
        "scene:\n"
        "  union:\n"
        "    - {}\n"
        "    - {{sphere: {{radius: 0.1}}, translate: [0.6, -4, 0.4], material: ball}}  # behind the camera\n",
        trap ? ", orbit_trap: {palette: [[0.9, 0.2, 0.1], [0.1, 0.9, 0.3], [0.2, 0.3, 1.0]], mix: 0.8}" : "",
        smooth ? "smooth_union: {radius: 0.3, children: [" + kids + "]}" : "union: [" + kids + "]"));
  };
  sdfrt::FloatImage smooth = render(scene(true, true), 8);
  sdfrt::FloatImage hard = render(scene(false, true), 8);  // the material id path
  sdfrt::FloatImage plain = render(scene(false, false), 8);
  int same_depth = 0, equal = 0, palette = 0, seam = 0;
  for (int y = 0; y < smooth.height; ++y)
    for (int x = 0; x < smooth.width; ++x) {
      float ds = smooth.at(3, x, y), dh = hard.at(3, x, y);
      if (ds < 0 || dh < 0) continue;
      if (ds != dh) {
        ++seam;
        continue;
      }
      ++same_depth;
      equal += diff(pixel(smooth, x, y), pixel(hard, x, y)) < 1e-4;
      palette += diff(pixel(hard, x, y), pixel(plain, x, y)) > 0.05;
    }
  SCOPED_TRACE(fmt::format("{} pixels at the same depth, {} equal, {} in palette colours, {} changed by the blend",
                           same_depth, equal, palette, seam));
  ASSERT_GT(same_depth, 500);
  EXPECT_GT(seam, 10) << "the smooth union should change the surface somewhere";
  EXPECT_GT(palette, same_depth / 4) << "the palette should colour much of the fractal";
  EXPECT_GE(equal, same_depth * 99 / 100);
}

}  // namespace
}  // namespace sdfc::e2e
