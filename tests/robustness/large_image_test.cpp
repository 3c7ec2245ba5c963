// The largest image renders band by band: 16384x16384 with the cheapest
// kernel, in far less memory than the image. Its own executable so it gets
// its own time limit (a quarter of a billion pixels through PNG).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdint>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

// One march step a pixel: the cost is the pixels themselves.
TEST(LargeImage, SixteenThousandSquaredRendersByTilesInBoundedMemory) {
  ScratchDir dir;
  std::string scene = dir.write("big.yaml", "render: {width: 16384, height: 16384, max_steps: 1}\n"
                                            "scene: {sphere: {radius: 1}}\n");
  RunResult r = run_sdfc("render " + scene + " -q -o " + dir.file("big.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  // The PNG header: signature, then IHDR's width and height (big-endian).
  std::string png = read_text(dir.file("big.png"));
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  auto be32 = [&](size_t at) {
    return std::uint32_t((unsigned char)png[at]) << 24 | std::uint32_t((unsigned char)png[at + 1]) << 16 |
           std::uint32_t((unsigned char)png[at + 2]) << 8 | std::uint32_t((unsigned char)png[at + 3]);
  };
  EXPECT_EQ(be32(16), 16384u);
  EXPECT_EQ(be32(20), 16384u);
  // Peak memory of the render (children of this test only): the float image
  // alone would be 16384^2 x 4 planes x 4 bytes = 4 GiB, its 8-bit RGB 768 MiB.
  rusage ru{};
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &ru), 0);
  EXPECT_LT(ru.ru_maxrss, 1536L * 1024) << "peak RSS in KiB";
  std::cerr << "peak RSS of the 16384x16384 render: " << ru.ru_maxrss / 1024 << " MiB\n";
}

}  // namespace
}  // namespace sdfc::test
