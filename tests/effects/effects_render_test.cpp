// Effects change the image where geometry says they must, and nowhere else.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "render_helpers.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/codegen/kernel_abi.hpp"

namespace sdfc {
namespace {

using test::brightness;
using test::project;
using test::render_text;

// Linear output (gamma 1, clamp) so pixel values are the shading's values.
const std::string kLinear = "render: {width: 160, height: 120, gamma: 1}\n";

std::string crease_scene(const std::string& effects) {
  return kLinear +
         "camera: {position: [3, -4, 3], target: [0, 0, 0.3], fov: 40}\n"
         "lights:\n  - ambient: {intensity: 1, color: [1, 1, 1]}\n" +
         effects +
         "scene:\n  union:\n    - plane: {}\n    - box: {size: [1, 1, 1]}\n      translate: [0, 0, 0.5]\n";
}

TEST(EffectsRender, AmbientOcclusionDarkensTheCrease) {
  auto off = render_text(crease_scene(""));
  for (const char* method : {"normal_samples", "step_count"}) {
    auto on = render_text(crease_scene(fmt::format("effects: {{ambient_occlusion: {{method: {}, strength: 4}}}}\n", method)));
    // Mean ratio on over off on the floor along the box's +x face, and far from it.
    double crease = 0, open = 0;
    int n_crease = 0, n_open = 0;
    for (int y = 0; y < on.image.height; ++y) {
      for (int x = 0; x < on.image.width; ++x) {
        auto p = test::world_point(on, x, y);
        if (!p || std::fabs((*p)[2]) > 1e-2) continue;  // floor only
        double ratio = brightness(on.image, {x, y}) / brightness(off.image, {x, y});
        if ((*p)[0] > 0.5 && (*p)[0] < 0.6 && std::fabs((*p)[1]) < 0.4) crease += ratio, ++n_crease;
        if (std::hypot((*p)[0], (*p)[1]) > 1.6) open += ratio, ++n_open;
      }
    }
    ASSERT_GT(n_crease, 3) << method;
    ASSERT_GT(n_open, 100) << method;
    crease /= n_crease;
    open /= n_open;
    EXPECT_LT(crease, 0.9) << method;
    if (std::string(method) == "normal_samples") {
      EXPECT_NEAR(open, 1.0, 1e-4);  // nothing within the probes' reach
      EXPECT_LT(crease, open - 0.1);
    }
    // step_count darkens wherever rays need many steps, grazing floors too,
    // so only the crease is checked for it.
  }
}

std::string shadow_scene(const char* kind) {
  return kLinear +
         "camera: {position: [1, -4, 4], target: [1, 0, 0], fov: 45}\n"
         "lights:\n  - ambient: {intensity: 0.2, color: [1, 1, 1]}\n"
         "  - directional: {direction: [1, 0, -1], shadows: " + std::string(kind) + "}\n"
         "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 0.5}\n      translate: [0, 0, 1]\n";
}

TEST(EffectsRender, HardShadowFallsWhereGeometrySays) {
  // The light travels along (1, 0, -1): the sphere's shadow on z = 0 is the
  // ellipse centred at (1, 0, 0) with semi-axes 0.5 / sin 45° along x and 0.5 along y.
  auto off = render_text(shadow_scene("none"));
  auto hard = render_text(shadow_scene("hard"));
  auto soft = render_text(shadow_scene("soft"));
  int inside = 0, outside = 0;
  for (int y = 0; y < hard.image.height; ++y) {
    for (int x = 0; x < hard.image.width; ++x) {
      auto p = test::world_point(hard, x, y);
      if (!p || std::fabs((*p)[2]) > 1e-2) continue;  // floor only
      double e = std::pow(((*p)[0] - 1) / (0.5 * std::sqrt(2.0)), 2) + std::pow((*p)[1] / 0.5, 2);
      // The rim moves by the shadow ray's start offset and hit epsilon (a few
      // pixel footprints); skip that band.
      if (e > 0.75 && e < 1.3) continue;
      float lit = brightness(off.image, {x, y}), shaded = brightness(hard.image, {x, y});
      if (e < 1) {
        ++inside;
        EXPECT_NEAR(shaded, 0.2f * 0.8f, 2e-3f) << (*p)[0] << "," << (*p)[1];  // ambient only
        if (e < 0.5) {
          EXPECT_LT(brightness(soft.image, {x, y}), 0.5f * lit) << (*p)[0] << "," << (*p)[1];
        }
      } else {
        ++outside;
        EXPECT_NEAR(shaded, lit, 1e-4f) << (*p)[0] << "," << (*p)[1];
      }
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 1000);
}

TEST(EffectsRender, FogBlendsTowardItsColourWithDistance) {
  const std::string base = kLinear +
                           "camera: {position: [0, -2, 1], target: [0, 5, 0], fov: 50}\n"
                           "lights:\n  - ambient: {intensity: 1, color: [1, 1, 1]}\n";
  const std::string scene = "scene: {plane: {}}\n";
  auto clear = render_text(base + scene);
  auto fog = render_text(base + "effects: {fog: {color: [1, 0, 0], density: 0.1}}\n" + scene);
  int checked = 0;
  float last_amount = -1;
  for (int y = clear.image.height - 1; y >= 0; y -= 4) {
    int x = clear.image.width / 2;
    float t = clear.image.at(3, x, y);
    if (t < 0) continue;
    float keep = std::exp(-0.1f * t);
    for (int c = 0; c < 3; ++c) {
      float fog_c = c == 0 ? 1.0f : 0.0f;
      EXPECT_NEAR(fog.image.at(c, x, y), fog_c + (clear.image.at(c, x, y) - fog_c) * keep, 2e-3f) << "row " << y;
    }
    float amount = 1 - keep;
    EXPECT_GT(amount, last_amount);  // rows further up are further away
    last_amount = amount;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(EffectsRender, DepthAovMatchesTheAnalyticSphere) {
  auto r = render_text("render: {width: 96, height: 64, hit_epsilon: 0.5}\n"
                       "camera: {position: [0, -5, 0.3], target: [0, 0, 0], fov: 40}\n"
                       "scene: {sphere: {radius: 1}}\n");
  const auto& img = r.image;
  std::vector<float> frame = codegen::frame_params(r.module.plan, img.width, img.height);
  auto f3 = [&](int i) {
    const int lo = i + abi::kLowPart;
    return ir::Vec3d{double(frame[i]) + frame[lo], double(frame[i + 1]) + frame[lo + 1], double(frame[i + 2]) + frame[lo + 2]};
  };
  ir::Vec3d ro = f3(abi::kEye), fw = f3(abi::kForward), rt = f3(abi::kRight), up = f3(abi::kUp);
  double pixel_angle = frame[abi::kPixelAngle];
  int hits = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      double u = 2.0 * (x + 0.5) / img.width - 1, v = 1 - 2.0 * (y + 0.5) / img.height;
      ir::Vec3d d{fw[0] + rt[0] * u + up[0] * v, fw[1] + rt[1] * u + up[1] * v, fw[2] + rt[2] * u + up[2] * v};
      double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (auto& c : d) c /= len;
      double b = ro[0] * d[0] + ro[1] * d[1] + ro[2] * d[2];
      double c = ro[0] * ro[0] + ro[1] * ro[1] + ro[2] * ro[2] - 1.0;
      double disc = b * b - c;
      float depth = img.at(3, x, y);
      if (disc < 0) {
        // Rays that pass within the hit epsilon of the surface count as hits.
        double closest = std::sqrt(1 - disc) - 1;
        if (closest > 0.5 * pixel_angle * 6) {
          EXPECT_EQ(depth, -1.0f) << x << "," << y;
        }
        continue;
      }
      double t = -b - std::sqrt(disc);
      double cos_view = std::sqrt(disc);  // = |dot(normal, ray)| for a unit sphere
      if (cos_view < 0.3) continue;       // near the silhouette the march may stop short by more
      ASSERT_GT(depth, 0.0f) << x << "," << y;
      // The march stops once the distance is below hit_epsilon * pixel footprint.
      double tol = 0.5 * pixel_angle * t / cos_view + 1e-5 * t;
      EXPECT_LE(depth, t + 1e-5 * t) << x << "," << y;
      EXPECT_GE(depth, t - tol) << x << "," << y;
      ++hits;
    }
  }
  EXPECT_GT(hits, 400);
}

const std::string kAllEffects =
    "render: {width: 96, height: 64, samples: 2, filter: tent, dither: true, exposure: 0.3, tone_mapping: aces}\n"
    "camera: {position: [3, -4, 2.5], target: [0, 0, 0.5], fov: 40, aperture: 0.05}\n"
    "lights:\n  - directional: {direction: [-0.6, 0.3, -0.7], shadows: soft}\n"
    "  - point: {position: [2, -2, 3], intensity: 4, shadows: hard}\n"
    "materials: {mirror: {reflectivity: 0.7}}\n"
    "effects:\n  ambient_occlusion: {}\n  glow: {step_strength: 0.1}\n  fog: {height_falloff: 0.3}\n"
    "  reflections: {depth: 2}\n"
    "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 0.7}\n      translate: [0, 0, 0.7]\n      material: mirror\n"
    "    - box: {size: [0.6, 0.6, 0.6]}\n      translate: [1.1, 0.3, 0.3]\n";

TEST(EffectsRender, TiledEqualsUntiledBitForBit) {
  auto whole = render_text(kAllEffects, 16, 4096);
  auto tiled = render_text(kAllEffects, 16, 32);  // 32 divides the image: one launch shape, one PoCL compile
  ASSERT_EQ(whole.image.data.size(), tiled.image.data.size());
  EXPECT_EQ(std::memcmp(whole.image.data.data(), tiled.image.data.data(), whole.image.data.size() * sizeof(float)), 0);
}

TEST(EffectsRender, EveryPacketShapeRendersTheSameImage) {
  // An image size no packet shape divides, with tiles that cut packets at
  // their edges too: every pixel must land in its place whatever the shape.
  std::string scene = kAllEffects;
  scene.replace(scene.find("width: 96, height: 64"), 21, "width: 37, height: 23");
  auto rows = render_text(scene, 16, 20, 1);
  for (int packet_rows : {2, 4, 16}) {
    auto other = render_text(scene, 16, 20, packet_rows);
    ASSERT_EQ(rows.image.data.size(), other.image.data.size());
    EXPECT_EQ(std::memcmp(rows.image.data.data(), other.image.data.data(), rows.image.data.size() * sizeof(float)), 0)
        << "16 lanes as " << 16 / packet_rows << "x" << packet_rows;
  }
  // packets wider than OpenCL's vectors (8x4 and 8x8) compute lane by lane the same floats
  for (int width : {32, 64}) {
    auto wide = render_text(scene, width, 20);
    ASSERT_EQ(rows.image.data.size(), wide.image.data.size());
    EXPECT_EQ(std::memcmp(rows.image.data.data(), wide.image.data.data(), rows.image.data.size() * sizeof(float)), 0)
        << width << " lanes";
  }
  // and one pixel per work-item agrees with the packets in nearly every pixel
  auto single = render_text(scene, 1, 20);
  int differing = 0;
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < single.image.plane_size(); ++i)
      differing += std::fabs(single.image.plane(c)[i] - rows.image.plane(c)[i]) > 4.0f / 255.0f;
  EXPECT_LE(differing, 3) << "of " << 3 * single.image.plane_size() << " channel values";
}

TEST(EffectsRender, EveryEffectBuildsAtEveryWidthAndPrecision) {
  for (const char* precision : {"float", "double"}) {
    if (std::string(precision) == "double" && !test::device().info().fp64) continue;
    std::string scene = kAllEffects + "\n";
    scene.replace(scene.find("render: {"), 9, fmt::format("render: {{precision: {}, ", precision));
    for (int width : {1, 4, 8, 16, 32, 64}) {
      auto r = render_text(scene, width);
      for (float v : r.image.data) ASSERT_TRUE(std::isfinite(v)) << precision << " width " << width;
    }
  }
}

}  // namespace
}  // namespace sdfc
