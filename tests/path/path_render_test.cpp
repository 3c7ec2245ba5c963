// The path integrator on PoCL against answers known without it: the white
// furnace, energy that never grows with the number of bounces, and pixels
// that do not depend on how the image is cut into tiles.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "render_helpers.hpp"
#include "sdfc/codegen/kernel_abi.hpp"

namespace sdfc {
namespace {

using test::render_text;

int plane(const char* name) { return abi::plane_index(name); }

// Mean of r, g, b over the pixels every sample of which hit (coverage 1).
double covered_mean(const sdfrt::FloatImage& img, int* count = nullptr) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (img.at(plane("hit"), x, y) < 1.0f) continue;
      for (int c = 0; c < 3; ++c) sum += img.at(c, x, y);
      ++n;
    }
  if (count) *count = n;
  return n ? sum / (3.0 * n) : 0;
}

double image_mean(const sdfrt::FloatImage& img) {
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = img.at(c, x, y);
        EXPECT_TRUE(std::isfinite(v)) << x << "," << y;
        sum += v;
      }
  return sum / (3.0 * img.width * img.height);
}

std::string furnace(const std::string& material, int samples, int bounces) {
  return fmt::format(
      "camera: {{position: [0, -4, 0], target: [0, 0, 0], fov: 30}}\n"
      "render: {{width: 24, height: 24, samples: {}, gamma: 1, integrator: path, max_bounces: {}}}\n"
      "background: [0.8, 0.8, 0.8]\nlights: []\n"
      "materials:\n  m: {}\n"
      "scene: {{sphere: {{radius: 1}}, material: m}}\n",
      samples, bounces, material);
}

// A diffuse sphere of albedo 0.5 under a uniform environment of 0.8, no
// lights: every path leaves the (convex) sphere after one bounce, so each
// pixel on it converges to 0.5 x 0.8 = 0.4.
TEST(PathRender, FurnaceConverges) {
  auto r = render_text(furnace("{color: [0.5, 0.5, 0.5]}", 256, 8));
  int n = 0;
  double mean = covered_mean(r.image, &n);
  EXPECT_GT(n, 100);
  EXPECT_NEAR(mean, 0.4, 0.004) << "furnace mean " << mean;
  // the camera sees the environment itself around the sphere
  EXPECT_NEAR(r.image.at(0, 0, 0), 0.8, 1e-5);
}

// A rough metal and a glossy dielectric never reflect more than they
// receive (the GGX lobe loses some energy at high roughness, never gains).
TEST(PathRender, GlossyFurnaceConservesEnergy) {
  for (const char* m : {"{color: [1, 1, 1], metalness: 1, roughness: 0.1}", "{color: [1, 1, 1], metalness: 1, roughness: 0.8}",
                        "{color: [1, 1, 1], roughness: 0.4}", "{color: [0.5, 0.5, 0.5], roughness: 0.05}"}) {
    auto r = render_text(furnace(m, 256, 8));
    double mean = covered_mean(r.image);
    EXPECT_LE(mean, 0.8 * 1.01) << m;
    EXPECT_GE(mean, 0.8 * 0.45) << m;
    image_mean(r.image);  // every pixel finite
  }
}

// Light that scatters more often only adds: the mean never falls as
// max_bounces grows, and the additions shrink (albedo < 1 converges).
TEST(PathRender, EnergyNeverGrowsWithBounces) {
  auto scene = [](int bounces) {
    return fmt::format(
        "camera: {{position: [2.5, -3, 1.5], target: [0, 0, 0.4], fov: 45}}\n"
        "render: {{width: 48, height: 32, samples: 16, gamma: 1, integrator: path, max_bounces: {}}}\n"
        "background: {{top: [0.6, 0.7, 0.9], bottom: [0.2, 0.2, 0.2]}}\n"
        "lights:\n  - directional: {{direction: [-0.4, 0.5, -0.75], intensity: 1, shadows: hard}}\n"
        "materials:\n  m: {{color: [0.7, 0.6, 0.5]}}\n"
        "scene:\n  union:\n    - plane: {{}}\n    - box: {{size: [1, 1, 1]}}\n      translate: [0, 0, 0.5]\n"
        "    - sphere: {{radius: 0.5}}\n      translate: [0.9, 0.9, 0.5]\n  material: m\n",
        bounces);
  };
  std::vector<double> means;
  std::vector<sdfrt::FloatImage> images;
  for (int b : {1, 2, 4, 8}) {
    auto r = render_text(scene(b));
    means.push_back(image_mean(r.image));
    images.push_back(r.image);
  }
  for (size_t i = 1; i < means.size(); ++i) {
    EXPECT_GE(means[i], means[i - 1] - 1e-6) << "bounces step " << i;
    // per pixel too: the same path, followed further
    for (int y = 0; y < images[i].height; ++y)
      for (int x = 0; x < images[i].width; ++x)
        ASSERT_GE(images[i].at(1, x, y), images[i - 1].at(1, x, y) - 1e-5f) << x << "," << y << " step " << i;
  }
  EXPECT_LT(means[3] - means[2], means[1] - means[0]) << "the additions must shrink";
  EXPECT_LT(means[3], 1.0);
}

// The firefly clamp only ever removes light, and only indirect light: a
// clamp far above every value changes nothing.
TEST(PathRender, FireflyClampOnlyDarkens) {
  auto scene = [](const std::string& clamp) {
    return "camera: {position: [2.5, -3, 1.5], target: [0, 0, 0.4], fov: 45}\n"
           "render: {width: 32, height: 24, samples: 8, gamma: 1, integrator: path, max_bounces: 4" + clamp + "}\n"
           "background: {top: [0.6, 0.7, 0.9], bottom: [0.2, 0.2, 0.2]}\n"
           "lights:\n  - point: {position: [1, -1, 2], intensity: 3, shadows: hard}\n"
           "materials:\n  m: {color: [0.7, 0.6, 0.5], roughness: 0.2}\n"
           "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 0.5}\n      translate: [0, 0, 0.5]\n  material: m\n";
  };
  auto free = render_text(scene(""));
  auto loose = render_text(scene(", firefly_clamp: 1000"));
  auto tight = render_text(scene(", firefly_clamp: 0.02"));
  double removed = 0;
  for (int y = 0; y < free.image.height; ++y)
    for (int x = 0; x < free.image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        ASSERT_NEAR(loose.image.at(c, x, y), free.image.at(c, x, y), 1e-6f) << x << "," << y;
        ASSERT_LE(tight.image.at(c, x, y), free.image.at(c, x, y) + 1e-6f) << x << "," << y;
        removed += free.image.at(c, x, y) - tight.image.at(c, x, y);
      }
  EXPECT_GT(removed, 0.0);
}

// Pixels are seeded by their absolute position and sample: tiles and
// packet shapes change nothing.
TEST(PathRender, TilesAndPacketsDoNotChangeThePixels) {
  const std::string s = furnace("{color: [0.6, 0.5, 0.4], roughness: 0.3}", 8, 4);
  auto whole = render_text(s, 16, 256);
  auto tiled = render_text(s, 16, 8);
  for (int y = 0; y < whole.image.height; ++y)
    for (int x = 0; x < whole.image.width; ++x)
      ASSERT_EQ(whole.image.at(0, x, y), tiled.image.at(0, x, y)) << x << "," << y;
  // one pixel per work-item draws the same numbers (rounding may part a rare path)
  auto scalar = render_text(s, 1, 256);
  double diff = 0;
  for (int y = 0; y < whole.image.height; ++y)
    for (int x = 0; x < whole.image.width; ++x) diff += std::fabs(whole.image.at(0, x, y) - scalar.image.at(0, x, y));
  EXPECT_LT(diff / (whole.image.width * whole.image.height), 2e-3);
}

// An emitter lights its neighbour: a floor beside a glowing sphere, no
// lights and a black environment, is lit only through emission.
TEST(PathRender, EmissionLightsTheScene) {
  auto r = render_text(
      "camera: {position: [0, -4, 2], target: [0, 0, 0], fov: 40}\n"
      "render: {width: 32, height: 24, samples: 32, gamma: 1, integrator: path, max_bounces: 3}\n"
      "background: [0, 0, 0]\nlights: []\n"
      "materials:\n  lamp: {color: [0, 0, 0], emission: [4, 3, 2]}\n"
      "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 0.5}\n      translate: [0, 0, 1]\n      material: lamp\n");
  auto p = test::project(r.module.plan, {0, 0, 1});
  EXPECT_NEAR(r.image.at(0, p.x, p.y), 1.0, 1e-5);  // the lamp itself, clamped by the tone curve
  auto floor = test::project(r.module.plan, {0.8, 0, 0});
  EXPECT_GT(test::brightness(r.image, floor), 0.05);
  image_mean(r.image);
}

// The sky: bluer above than at the horizon, finite everywhere, under both
// integrators; a low sun turns the horizon warm.
TEST(PathRender, SkyLooksLikeASky) {
  for (const char* integrator : {"direct", "path"}) {
    for (const char* sun : {"[0.3, -0.5, 0.8]", "[0.2, 1, 0.05]"}) {
      auto r = render_text(fmt::format(
          "camera: {{position: [0, -6, 0.5], target: [0, 0, 1.5], fov: 70}}\n"
          "render: {{width: 32, height: 32, samples: 4, gamma: 1, integrator: {}, max_bounces: 2}}\n"
          "background: {{sky: {{sun_direction: {}, turbidity: 3}}}}\n"
          "scene: {{sphere: {{radius: 0.5}}}}\n",
          integrator, sun));
      image_mean(r.image);
      const int top = 0, horizon = 19;  // 2 degrees above the horizon
      EXPECT_GT(r.image.at(2, 2, top), r.image.at(0, 2, top)) << integrator << sun << ": the zenith is blue";
      EXPECT_GT(r.image.at(0, 2, horizon) / r.image.at(2, 2, horizon), r.image.at(0, 2, top) / r.image.at(2, 2, top))
          << integrator << sun << ": the horizon is paler or warmer than the zenith";
    }
  }
}

}  // namespace
}  // namespace sdfc
