// Analytic silhouette: a unit sphere seen from (0, -5, 0) at 64x64. Each
// pixel's ray is computed here from the camera (the kernel's convention) and
// intersected with the sphere in closed form; the kernel's hit mask and
// depth must match, at SIMD width 1 and 8, in float and double.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "e2e_support.hpp"

namespace sdfc::e2e {
namespace {

using test::add;
using test::dot;
using test::mul;
using test::norm;

struct Config {
  int simd_width;
  bool dbl;
};

void PrintTo(const Config& c, std::ostream* os) { *os << "w" << c.simd_width << (c.dbl ? "_double" : "_float"); }

class SphereSilhouette : public ::testing::TestWithParam<Config> {};

TEST_P(SphereSilhouette, MatchesAnalyticIntersection) {
  const Config c = GetParam();
  constexpr int W = 64, H = 64;
  // hit_epsilon 0.1 (not the default 0.5) makes the depth bound five times
  // tighter: a sphere 0.1% too big already fails it.
  ir::Module m = test::compile_text(fmt::format(
      "camera: {{position: [0, -5, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}}\n"
      "render: {{width: {}, height: {}, precision: {}, hit_epsilon: 0.1}}\n"
      "scene: {{sphere: {{radius: 1}}}}\n",
      W, H, c.dbl ? "double" : "float"));
  const double hit_eps = m.plan.march.hit_epsilon;
  sdfrt::FloatImage img = render(m, c.simd_width);
  ASSERT_EQ(img.width, W);
  ASSERT_EQ(img.height, H);
  CameraRays cam(m.plan.camera, W, H);
  const V3 ro = cam.origin;

  int hits = 0, misses = 0, edge = 0, mask_bad = 0, depth_bad = 0;
  double worst_depth = 0;  // |t - t_exact| over what is allowed
  std::string msgs;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      V3 rd = cam.direction(x, y);
      // |ro + t rd|^2 = 1  ->  t^2 + 2 b t + c = 0
      double b = dot(ro, rd), cc = dot(ro, ro) - 1.0, disc = b * b - cc;
      double miss_by = std::sqrt(std::max(0.0, dot(ro, ro) - b * b)) - 1.0;  // ray-to-centre distance - radius
      double footprint = cam.pixel_angle * -b;  // one pixel at the sphere's distance
      float depth = img.at(3, x, y);
      bool got_hit = depth >= 0;
      if (std::fabs(miss_by) <= footprint) {  // within a pixel of the silhouette: either verdict is right
        ++edge;
        continue;
      }
      bool want_hit = disc >= 0;
      (want_hit ? hits : misses)++;
      if (got_hit != want_hit) {
        if (mask_bad++ < 5)
          msgs += fmt::format("  pixel ({}, {}): analytic {}, kernel depth {}\n", x, y, want_hit ? "hit" : "miss", depth);
        continue;
      }
      if (!want_hit) {
        EXPECT_EQ(depth, -1.0f) << "a miss must have depth -1";
        continue;
      }
      double t_exact = -b - std::sqrt(disc);
      V3 n = mul(add(ro, mul(rd, t_exact)), 1.0);  // unit normal (radius 1)
      double cos_in = -dot(rd, n);                 // cosine of the incidence angle
      // The march stops as soon as d < hit_eps * footprint(t), never past the
      // surface (the sphere's distance is exact and step_factor is 1), so
      // the point reached is at most that far outside; along the ray that is
      // up to hit_eps * footprint / cos(incidence). Float rays and t add a
      // little (1e-5 relative).
      double tol = 1e-5 * t_exact + 1e-5;
      double allowed = hit_eps * cam.pixel_angle * depth / cos_in + tol;
      double gap = t_exact - depth;
      worst_depth = std::max(worst_depth, std::fabs(gap) / allowed);
      double d_at = norm(add(ro, mul(rd, double(depth)))) - 1.0;
      if (gap < -tol || gap > allowed || d_at > hit_eps * cam.pixel_angle * depth + tol) {
        if (depth_bad++ < 5)
          msgs += fmt::format("  pixel ({}, {}): depth {} vs analytic {} (allowed gap {}, surface distance {})\n", x, y,
                              depth, t_exact, allowed, d_at);
      }
    }
  EXPECT_EQ(mask_bad, 0) << msgs;
  EXPECT_EQ(depth_bad, 0) << msgs;
  // The scene must really exercise both verdicts, with a thin edge band:
  // the disc has a radius of ~18 px, so ~1000 hits and ~3000 misses.
  EXPECT_GT(hits, 800);
  EXPECT_GT(misses, 2500);
  EXPECT_LT(edge, 400);
  RecordProperty("worst_depth_over_allowed", fmt::format("{:.3g}", worst_depth));
}

INSTANTIATE_TEST_SUITE_P(Sphere, SphereSilhouette,
                         ::testing::Values(Config{1, false}, Config{8, false}, Config{1, true}, Config{8, true}),
                         [](const auto& info) {
                           return fmt::format("w{}_{}", info.param.simd_width, info.param.dbl ? "double" : "float");
                         });

}  // namespace
}  // namespace sdfc::e2e
