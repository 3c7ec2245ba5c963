// Artefacts a viewer would notice, measured on real renders: rings in a soft
// shadow's penumbra, and streaks where a smooth union meets a Mandelbulb.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render_helpers.hpp"
#include "test_files.hpp"

namespace sdfc {
namespace {

using test::brightness;
using test::render_text;
using test::world_point;

// A power-8 Mandelbulb over a floor, a low soft light: the penumbra falls on
// open floor (the scene of examples/animated.yaml, without the props).
const std::string kShadowScene =
    "render: {width: 320, height: 180, gamma: 1}\n"
    "camera: {position: [0, -4.6, 1.4], target: [0, 0, -0.3], up: [0, 0, 1], fov: 44}\n"
    "lights:\n"
    "  - directional: {direction: [-0.5, 0.6, -0.62], intensity: 1.3, shadows: soft, softness: 12, shadow_steps: 128}\n"
    "  - ambient: {intensity: 0.35}\n"
    "scene:\n  union:\n    - plane: {offset: -1.05}\n    - mandelbulb: {power: 8, iterations: 8}\n";

// Rings are ripples: along an image row the floor's brightness (ambient plus
// the shadowed light; nothing else varies on a flat floor under a
// directional light) bends up and down at pixel scale. A penumbra, however
// sharp, bends smoothly; a ring is a kink in it. The measure is the second
// difference of brightness along rows of open floor (away from the bulb's
// foot, where its own bumps shape the shadow).
struct Banding {
  int kinks = 0;       // pixels whose |second difference| exceeds kKink
  double worst = 0;    // the largest |second difference|
};
constexpr double kKink = 0.15;

Banding floor_banding(const test::Rendered& r) {
  Banding b;
  for (int y = 0; y < r.image.height; ++y) {
    for (int x = 1; x + 1 < r.image.width; ++x) {
      bool open = true;
      for (int dx = -1; dx <= 1; ++dx) {
        auto p = world_point(r, x + dx, y);
        open = open && p && std::fabs((*p)[2] + 1.05) < 1e-2 && std::hypot((*p)[0], (*p)[1]) > 1.3;
      }
      if (!open) continue;
      double d2 = std::fabs(brightness(r.image, {x - 1, y}) - 2 * brightness(r.image, {x, y}) + brightness(r.image, {x + 1, y}));
      b.worst = std::max(b.worst, d2);
      if (d2 > kKink) ++b.kinks;
    }
  }
  return b;
}

TEST(Artefacts, SoftShadowPenumbraHasNoRings) {
  Banding b = floor_banding(render_text(kShadowScene));
  std::printf("largest second difference on the floor %.3f, %d pixels above %.2f\n", b.worst, b.kinks, kKink);
  EXPECT_EQ(b.kinks, 0);
  EXPECT_LT(b.worst, 0.15);
}

// A power-3 Mandelbulb smoothly united with a sphere, default normals.
const std::string kSeamScene =
    "render: {width: 320, height: 180, gamma: 1}\n"
    "camera: {position: [0, -3.2, 0.8], target: [0, 0, 0], up: [0, 0, 1], fov: 45}\n"
    "lights:\n  - directional: {direction: [-0.5, 0.6, -0.6], intensity: 1.0}\n  - ambient: {intensity: 0.25}\n"
    "scene:\n  smooth_union:\n    radius: 0.3\n    children:\n"
    "      - mandelbulb: {power: 3, iterations: 10}\n"
    "      - sphere: {radius: 0.6}\n        translate: [1.0, 0, 0.3]\n";

// Streaks are normals that flip between neighbouring pixels of a smooth
// surface: on the sphere and the seam (within 0.1 of the sphere), the angle
// between a pixel's normal and its right and lower neighbours' stays small.
TEST(Artefacts, SphereSmoothUnitedWithMandelbulbHasCleanNormals) {
  auto r = render_text(kSeamScene);
  const ir::Vec3d c{1.0, 0, 0.3};
  auto on_sphere = [&](int x, int y) {
    auto p = world_point(r, x, y);
    if (!p) return false;
    double dx = (*p)[0] - c[0], dy = (*p)[1] - c[1], dz = (*p)[2] - c[2];
    return std::fabs(std::sqrt(dx * dx + dy * dy + dz * dz) - 0.6) < 0.1;
  };
  auto cos_between = [&](int x0, int y0, int x1, int y1) {
    double s = 0;
    for (int k = 4; k < 7; ++k) s += r.image.at(k, x0, y0) * r.image.at(k, x1, y1);
    return s;
  };
  int pixels = 0, flips = 0;
  for (int y = 0; y + 1 < r.image.height; ++y)
    for (int x = 0; x + 1 < r.image.width; ++x) {
      if (!on_sphere(x, y) || !on_sphere(x + 1, y) || !on_sphere(x, y + 1)) continue;
      ++pixels;
      if (std::min(cos_between(x, y, x + 1, y), cos_between(x, y, x, y + 1)) < std::cos(30 * 3.14159265 / 180)) ++flips;
    }
  std::printf("%d of %d sphere pixels turn by > 30 deg to a neighbour\n", flips, pixels);
  ASSERT_GT(pixels, 1000);
  EXPECT_LT(flips, pixels / 200);
}

// Grain: the KIFS's folds leave detail far below a pixel, so one sample per
// pixel picks a random facet (and its normal) in each: aliasing of real
// detail, not estimator noise (a finer march changes nothing). The measure
// is the image's high-frequency energy (its difference from a 3x3 box blur)
// over the fractal; the example's own settings must come within 25 % of a
// converged 32-sample render of the same view (at one sample: 3x).
double high_frequency(const sdfrt::FloatImage& img) {
  double sum = 0;
  int n = 0;
  for (int y = 1; y + 1 < img.height; ++y)
    for (int x = 1; x + 1 < img.width; ++x) {
      if (img.at(3, x, y) < 0) continue;  // background
      double blur = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) blur += brightness(img, {x + dx, y + dy}) / 9;
      double e = brightness(img, {x, y}) - blur;
      sum += e * e;
      ++n;
    }
  return n ? std::sqrt(sum / n) : 0;
}

TEST(Artefacts, KifsExampleIsNotGrainy) {
  auto at_size = [](int samples) {
    ir::Module m = test::compile_text(test::read_text_file(std::string(SDFC_SOURCE_DIR) + "/examples/kifs.yaml"));
    m.plan.march.width = 320;
    m.plan.march.height = 180;
    if (samples) {
      m.plan.march.samples = samples;
      m.plan.march.filter = ir::MarchSettings::Filter::Tent;
    }
    return m;
  };
  double example = high_frequency(test::render_module(at_size(0)).image);
  double converged = high_frequency(test::render_module(at_size(32)).image);
  std::printf("high-frequency energy: example %.4f, converged %.4f\n", example, converged);
  EXPECT_LT(example, 1.25 * converged);
}

}  // namespace
}  // namespace sdfc
