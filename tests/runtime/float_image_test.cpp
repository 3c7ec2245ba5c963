// FloatImage keeps the planes of a dropped frame for the next one (a fresh
// mapping per frame costs a page fault per 4 KiB): the block must come back
// zeroed, only to an image it fits, and copies must stay independent.
#include <sdfrt/float_image.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace sdfrt {
namespace {

const std::vector<std::string> kPlanes = {"r", "g", "b", "depth", "normal_x", "normal_y", "normal_z", "steps"};

bool all_zero(const FloatImage& img) {
  return std::all_of(img.data.begin(), img.data.end(), [](float v) { return v == 0.0f; });
}

TEST(FloatImage, ADroppedFramesPlanesComeBackZeroedForTheNextFrame) {
  const float* block = nullptr;
  {
    FloatImage a(1280, 720, kPlanes);
    std::fill(a.data.begin(), a.data.end(), 7.0f);
    block = a.data.data();
  }
  FloatImage b(1280, 720, kPlanes);
  EXPECT_EQ(b.data.data(), block);
  EXPECT_EQ(b.data.size(), size_t(1280) * 720 * kPlanes.size());
  EXPECT_TRUE(all_zero(b));
}

TEST(FloatImage, MoveAssigningOverAFrameKeepsItsPlanes) {
  FloatImage shown(640, 360, kPlanes);
  std::fill(shown.data.begin(), shown.data.end(), 3.0f);
  const float* old_block = shown.data.data();
  shown = FloatImage(640, 360, kPlanes);  // the viewer's loop: the new frame replaces the shown one
  EXPECT_TRUE(all_zero(shown));
  FloatImage next(640, 360, kPlanes);
  EXPECT_EQ(next.data.data(), old_block);
  EXPECT_TRUE(all_zero(next));
}

TEST(FloatImage, AKeptBlockGoesOnlyToAnImageItFits) {
  const float* big = nullptr;
  {
    FloatImage a(1920, 1080, kPlanes);
    big = a.data.data();
  }
  FloatImage small(256, 256, kPlanes);  // more than twice smaller: a block of its own
  EXPECT_NE(small.data.data(), big);
  FloatImage larger(2560, 1440, kPlanes);  // too large for the kept block
  EXPECT_NE(larger.data.data(), big);
  EXPECT_TRUE(all_zero(small));
  EXPECT_TRUE(all_zero(larger));
}

TEST(FloatImage, CopiesAreIndependent) {
  FloatImage a(800, 600, kPlanes);
  a.data[5] = 1.0f;
  FloatImage b = a;
  b.data[5] = 2.0f;
  EXPECT_EQ(a.data[5], 1.0f);
  EXPECT_NE(a.data.data(), b.data.data());
  FloatImage c(800, 600, kPlanes);
  c = a;
  EXPECT_EQ(c.data[5], 1.0f);
}

}  // namespace
}  // namespace sdfrt
