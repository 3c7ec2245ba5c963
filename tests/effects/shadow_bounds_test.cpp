// Shadow rays in a scene of bounded parts on a floor stop as soon as nothing
// can block them or darken their penumbra any more (ShadowBounds,
// shadow_soft_open): the picture must be the one the full march gives.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "render_helpers.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc {
namespace {

using test::compile_text;
using test::render_module;

// A sphere and a box on a floor, lit by a rising directional light (soft),
// a point light (soft, per-lane test), a rising hard light and a grazing
// soft light whose penumbra the floor itself darkens (no early stop).
const std::string kFloorScene =
    "render: {width: 96, height: 64}\n"
    "camera: {position: [0, -4, 2], target: [0, 0, 0], up: [0, 0, 1], fov: 45}\n"
    "lights:\n"
    "  - directional: {direction: [-0.3, 0.5, -0.5], intensity: 0.6, shadows: soft, softness: 8}\n"
    "  - point: {position: [1.5, -1, 1.5], intensity: 1.5, shadows: soft, softness: 8}\n"
    "  - directional: {direction: [0.4, 0.3, -0.6], intensity: 0.3, shadows: hard}\n"
    "  - directional: {direction: [0.9, 0.1, -0.05], intensity: 0.3, shadows: soft, softness: 4}\n"
    "scene:\n  union:\n"
    "    - sphere: {radius: 0.5}\n"
    "    - box: {size: [0.4, 0.4, 0.4]}\n      translate: [1, 0.5, -0.3]\n"
    "    - plane: {normal: [0, 0, 1], offset: -0.5}\n";

std::string kernel_of(const ir::Module& m) {
  codegen::EmitOptions opt;
  opt.simd_width = 16;
  return codegen::emit_opencl(m, opt).source;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ShadowBounds, FloorScenesStopShadowRaysEarlyWithTheSamePicture) {
  ir::Module early = compile_text(kFloorScene);
  ASSERT_TRUE(early.analyses.shadow_bounds.has_value());
  EXPECT_EQ(early.analyses.shadow_bounds->plane_normals.size(), 1u);
  const std::string k = kernel_of(early);
  // the rising soft lights stop early; the grazing one (4 x 0.05 < 1) marches on
  EXPECT_EQ(count(k, "shadow_soft_open(TIME_ARG shadow_origin"), 2);
  EXPECT_EQ(count(k, "shadow_soft(TIME_ARG shadow_origin"), 1);
  EXPECT_EQ(count(k, "shadow_hard(TIME_ARG shadow_origin"), 1);
  EXPECT_EQ(count(k, "2.0f * footprint, ray_box_exit("), 1);  // the rising hard light ends at the parts' box

  ir::Module full = early;
  full.analyses.shadow_bounds.reset();  // every shadow ray marches to its end
  const std::string k_full = kernel_of(full);
  EXPECT_EQ(count(k_full, "shadow_soft_open"), 0);

  auto a = render_module(std::move(early)), b = render_module(std::move(full));
  ASSERT_EQ(a.image.data.size(), b.image.data.size());
  EXPECT_EQ(std::memcmp(a.image.data.data(), b.image.data.data(), a.image.data.size() * sizeof(float)), 0);
}

TEST(ShadowBounds, OnlyUnionsOfBoundedPartsAndPlanes) {
  auto bounds = [](const std::string& scene) {
    return compile_text("render: {width: 32, height: 32}\nscene:\n" + scene).analyses.shadow_bounds.has_value();
  };
  EXPECT_TRUE(bounds("  union:\n    - sphere: {}\n    - plane: {}\n"));
  EXPECT_FALSE(bounds("  sphere: {}\n"));  // bounded: ray_bounds serves
  EXPECT_TRUE(bounds("  union:\n    - sphere: {}\n    - plane: {}\n    - plane: {normal: [1, 0, 0], offset: -3}\n"));
  // an unbounded part other than a plane: an endless repetition
  EXPECT_FALSE(bounds("  union:\n    - sphere: {radius: 0.2}\n      repeat: {period: [1, 1, 1]}\n    - plane: {}\n"));
  EXPECT_FALSE(bounds("  smooth_union:\n    radius: 0.2\n    children:\n      - sphere: {}\n      - plane: {}\n"));
}

}  // namespace
}  // namespace sdfc
