// A catalogue primitive with numbers that are expressions of time, rendered
// by the real binary as a two-frame sequence: the frames differ, and frame 1
// looks like the same scene written with the values at time 1 (the numbers
// below are the expressions evaluated at time = 1 s).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <sdfrt/image_read.hpp>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::run_sdfc;
using sdfc::test::ScratchDir;

const char* kHead =
    "camera: {position: [0, -3.2, 1.4], target: [0, 0, 0], fov: 40}\n"
    "render: {width: 96, height: 64}\n";

double mean_abs_diff(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  EXPECT_EQ(a.data.size(), b.data.size());
  double sum = 0;
  for (size_t i = 0; i < a.data.size() && i < b.data.size(); ++i) sum += std::fabs(a.data[i] - b.data[i]);
  return sum / double(a.data.size());
}

TEST(AnimatedCatalogue, FramesFollowTheExpressionsOfTime) {
  ScratchDir dir;
  // link.length and cone.radius move; sin(1) = 0.841470984807897.
  std::string moving = dir.write(
      "moving.yaml", std::string(kHead) +
                         "scene:\n  union:\n"
                         "    - {link: {length: \"0.4 + 0.35*sin(time)\", major_radius: 0.3, minor_radius: 0.08}, "
                         "translate: [-0.6, 0, 0]}\n"
                         "    - {cone: {radius: \"0.35 + 0.2*sin(time)\", height: 0.8}, translate: [0.6, 0, 0]}\n");
  std::string still = dir.write(
      "still.yaml", std::string(kHead) +
                        fmt::format("scene:\n  union:\n"
                                    "    - {{link: {{length: {}, major_radius: 0.3, minor_radius: 0.08}}, "
                                    "translate: [-0.6, 0, 0]}}\n"
                                    "    - {{cone: {{radius: {}, height: 0.8}}, translate: [0.6, 0, 0]}}\n",
                                    0.4 + 0.35 * std::sin(1.0), 0.35 + 0.2 * std::sin(1.0)));
  auto r = run_sdfc(fmt::format("render {} --frames 0:1 --fps 1 -q -o {}/f_%d.png", moving, dir.path()));
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_sdfc(fmt::format("render {} -q -o {}/still.png", still, dir.path()));
  ASSERT_EQ(r.code, 0) << r.err;
  sdfrt::FloatImage f0 = sdfrt::read_png(dir.file("f_0.png")), f1 = sdfrt::read_png(dir.file("f_1.png")),
                    s1 = sdfrt::read_png(dir.file("still.png"));
  double moved = mean_abs_diff(f0, f1), off = mean_abs_diff(f1, s1);
  EXPECT_GT(moved, 0.01) << "the frames at time 0 and 1 should differ";
  EXPECT_LT(off, moved / 20) << "frame 1 should look like the scene at time 1";
}

}  // namespace
