#include <sdfrt/errors.hpp>
#include <sdfrt/renderer.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstring>

namespace sdfrt {
namespace {

using test::same_bits;

// Odd sizes so edge tiles, clamping and SIMD padding are all exercised.
constexpr int kWidth = 100;
constexpr int kHeight = 37;
constexpr float kFrame0 = 0.625f;

RenderOptions tiles_of(int size) {
  RenderOptions options;
  options.tile_width = size;
  options.tile_height = size;
  return options;
}

void expect_gradient(const FloatImage& image) {
  ASSERT_EQ(image.width, kWidth);
  ASSERT_EQ(image.height, kHeight);
  ASSERT_EQ(image.plane_names, (std::vector<std::string>{"r", "g", "b", "depth"}));
  ASSERT_EQ(image.data.size(), 4u * kWidth * kHeight);
  int mismatches = 0;
  for (int k = 0; k < 4; ++k) {
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const float want = test::expected_gradient(k, x, y, kWidth, kHeight, kFrame0);
        if (image.at(k, x, y) != want && ++mismatches <= 5) {
          ADD_FAILURE() << "plane " << k << " pixel (" << x << "," << y << "): got "
                        << image.at(k, x, y) << ", want " << want;
        }
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

class RendererBySimd : public ::testing::TestWithParam<int> {};

TEST_P(RendererBySimd, EveryPixelOfTiledRenderIsExact) {
  Renderer renderer(test::test_device(), test::gradient_spec(GetParam()));
  RenderStats stats;
  const FloatImage image = renderer.render({kFrame0}, kWidth, kHeight, tiles_of(16), &stats);
  expect_gradient(image);
  EXPECT_EQ(stats.tiles, 7 * 3);
  EXPECT_GT(stats.kernel_ms, 0.0);
  EXPECT_GE(stats.total_ms, stats.kernel_ms);
  EXPECT_EQ(renderer.last_render_stats().tiles, stats.tiles);
}

TEST_P(RendererBySimd, TiledEqualsUntiledBitForBit) {
  Renderer renderer(test::test_device(), test::gradient_spec(GetParam()));
  const FloatImage tiled = renderer.render({kFrame0}, kWidth, kHeight, tiles_of(16));
  const FloatImage untiled = renderer.render({kFrame0}, kWidth, kHeight, RenderOptions{});
  EXPECT_EQ(renderer.last_render_stats().tiles, 1);
  EXPECT_TRUE(same_bits(tiled, untiled));
  RenderOptions strips;  // non-square tiles
  strips.tile_width = 33;
  strips.tile_height = 5;
  EXPECT_TRUE(same_bits(tiled, renderer.render({kFrame0}, kWidth, kHeight, strips)));
  RenderOptions uniform = tiles_of(16);
  uniform.uniform_launch = true;
  EXPECT_TRUE(same_bits(tiled, renderer.render({kFrame0}, kWidth, kHeight, uniform)));
}

INSTANTIATE_TEST_SUITE_P(Simd, RendererBySimd, ::testing::Values(1, 8),
                         [](const auto& info) { return "width" + std::to_string(info.param); });

TEST(Renderer, ScalarAndSimd8KernelsAgree) {
  Renderer scalar(test::test_device(), test::gradient_spec(1));
  Renderer simd8(test::test_device(), test::gradient_spec(8));
  EXPECT_TRUE(same_bits(scalar.render({kFrame0}, kWidth, kHeight, tiles_of(16)),
                        simd8.render({kFrame0}, kWidth, kHeight, tiles_of(16))));
}

TEST(Renderer, FrameChangesBetweenRendersWithoutRebuild) {
  Renderer renderer(test::test_device(), test::gradient_spec(1));
  const BuildStats build = renderer.build_stats();
  EXPECT_EQ(renderer.render({0.5f}, 9, 3).at(2, 4, 1), 0.5f);
  EXPECT_EQ(renderer.render({0.75f, 1.0f, 2.0f}, 9, 3).at(2, 4, 1), 0.75f);
  EXPECT_EQ(renderer.render({}, 9, 3).at(2, 4, 1), 0.0f) << "empty frame reads as zeros";
  EXPECT_EQ(renderer.build_stats().build_ms, build.build_ms);
}

TEST(Renderer, ReportsProgressPerTile) {
  Renderer renderer(test::test_device(), test::gradient_spec(8));
  std::vector<std::pair<int, int>> calls;
  RenderOptions options = tiles_of(16);
  options.progress = [&](int done, int total) { calls.emplace_back(done, total); };
  renderer.render({kFrame0}, kWidth, kHeight, options);
  ASSERT_EQ(calls.size(), 22u);
  for (int i = 0; i <= 21; ++i) EXPECT_EQ(calls[static_cast<std::size_t>(i)], std::make_pair(i, 21));
}

TEST(Renderer, CancelFlagStopsBetweenTilesAndRendererStaysUsable) {
  Renderer renderer(test::test_device(), test::gradient_spec(1));
  std::atomic<bool> cancel{false};
  int last_done = 0;
  RenderOptions options = tiles_of(16);
  options.cancel = &cancel;
  options.progress = [&](int done, int) {
    last_done = done;
    if (done == 3) cancel = true;
  };
  EXPECT_THROW(renderer.render({kFrame0}, kWidth, kHeight, options), Cancelled);
  EXPECT_EQ(last_done, 3);

  cancel = false;
  options.progress = nullptr;
  expect_gradient(renderer.render({kFrame0}, kWidth, kHeight, options));
}

TEST(Renderer, RefusesBadSizes) {
  Renderer renderer(test::test_device(), test::gradient_spec(1));
  for (auto [w, h] : {std::pair{0, 10}, {10, 0}, {-3, 10}, {16385, 10}, {10, 20000}}) {
    EXPECT_THROW(renderer.render({kFrame0}, w, h), std::invalid_argument) << w << "x" << h;
  }
  RenderOptions zero_tiles = tiles_of(0);
  EXPECT_THROW(renderer.render({kFrame0}, 10, 10, zero_tiles), std::invalid_argument);
}

TEST(Renderer, RefusesTileLargerThanDeviceAllocation) {
  KernelSpec spec = test::gradient_spec(1);
  spec.planes.assign(64, "p");  // host-side only: the kernel is never launched
  Renderer renderer(test::test_device(), spec);
  try {
    renderer.render({kFrame0}, 16384, 16384, tiles_of(16384));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("maximum allocation"), std::string::npos) << e.what();
  }
}

TEST(Renderer, RejectsInvalidSpec) {
  KernelSpec no_planes = test::gradient_spec(1);
  no_planes.planes.clear();
  EXPECT_THROW(Renderer(test::test_device(), no_planes), std::invalid_argument);
  KernelSpec wrong_entry = test::gradient_spec(1);
  wrong_entry.entry = "not_there";
  EXPECT_THROW(Renderer(test::test_device(), wrong_entry), DeviceError);
}

TEST(FloatImage, IndexingAndPlaneLookup) {
  FloatImage image(3, 2, {"r", "depth"});
  image.data[1 * 6 + 1 * 3 + 2] = 7.0f;
  EXPECT_EQ(image.at(1, 2, 1), 7.0f);
  EXPECT_EQ(image.plane_index("depth"), 1);
  EXPECT_EQ(image.plane_index("nope"), -1);
  EXPECT_THROW(image.at(2, 0, 0), std::out_of_range);
  EXPECT_THROW(image.at(0, 3, 0), std::out_of_range);
}

}  // namespace
}  // namespace sdfrt
