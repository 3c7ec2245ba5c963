// sdfc compare's metrics on renders whose errors are known by construction,
// written and read back through the real image files.
#include <gtest/gtest.h>
#include <sdfrt/image_io.hpp>
#include <sdfrt/image_metrics.hpp>

#include <cmath>
#include <filesystem>
#include <random>

namespace sdfrt {
namespace {

constexpr int kW = 40, kH = 30;

struct Scene {
  FloatImage beauty{kW, kH, {"r", "g", "b"}};
  FloatImage depth{kW, kH, {"depth"}};
  FloatImage normal{kW, kH, {"normal.x", "normal.y", "normal.z"}};
};

// Hits in the left half (x < hit_columns) at depth 2 + x/10, normals along z
// tilted by `tilt_deg` about y; a smooth colour ramp.
Scene make(int hit_columns, double depth_scale, double tilt_deg, float colour_offset) {
  Scene s;
  double t = tilt_deg * M_PI / 180;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      size_t i = size_t(y) * kW + x;
      bool hit = x < hit_columns;
      s.depth.plane(0)[i] = hit ? float((2 + x / 10.0) * depth_scale) : -1.0f;
      s.normal.plane(0)[i] = hit ? float(std::sin(t)) : 0.0f;
      s.normal.plane(2)[i] = hit ? float(std::cos(t)) : 0.0f;
      s.beauty.plane(0)[i] = float(x * 4) / 255.0f + colour_offset;
      s.beauty.plane(1)[i] = float(y * 4) / 255.0f + colour_offset;
      s.beauty.plane(2)[i] = 0.2f + colour_offset;
    }
  return s;
}

std::string save(const Scene& s, const std::string& stem) {
  auto dir = std::filesystem::path(::testing::TempDir()) / "metrics";
  std::filesystem::create_directories(dir);
  std::string png = (dir / (stem + ".png")).string();
  write_png(png, s.beauty);
  write_pfm((dir / (stem + ".depth.pfm")).string(), s.depth, 0);
  write_pfm_rgb((dir / (stem + ".normal.pfm")).string(), s.normal, {0, 1, 2});
  return png;
}

TEST(ImageMetrics, IdenticalRendersHaveNoError) {
  std::string a = save(make(20, 1, 0, 0), "same_a"), b = save(make(20, 1, 0, 0), "same_b");
  ComparisonMetrics m = compare_renders(load_render_outputs(a), load_render_outputs(b));
  EXPECT_TRUE(m.has_depth && m.has_normal);
  EXPECT_EQ(m.hit_mask_disagreement_pct, 0);
  EXPECT_EQ(m.depth_rel_error_p99, 0);
  EXPECT_NEAR(m.normal_error_deg_p99, 0, 0.05);  // float normals, re-normalised by nobody
  EXPECT_TRUE(std::isinf(m.psnr_db));
  EXPECT_EQ(m.pixels_differing_pct, 0);
  EXPECT_DOUBLE_EQ(m.ssim, 1.0);
  EXPECT_NE(format_json(m).find("\"psnr_db\": null"), std::string::npos);
}

// Holes (the reference hits, the test misses) and hits behind the
// reference's surface count as passing it; extra hits in front do not.
TEST(ImageMetrics, HolesAndOvershootAreCounted) {
  std::string ref = save(make(20, 1, 0, 0), "pass_ref");
  ComparisonMetrics fewer = compare_renders(load_render_outputs(ref), load_render_outputs(save(make(17, 1, 0, 0), "holes")));
  EXPECT_NEAR(fewer.holes_pct, 100.0 * 3 * kH / (kW * kH), 1e-9);
  EXPECT_NEAR(fewer.passed_pct, fewer.holes_pct, 1e-9);
  ComparisonMetrics behind = compare_renders(load_render_outputs(ref), load_render_outputs(save(make(20, 1.02, 0, 0), "behind")));
  EXPECT_EQ(behind.holes_pct, 0);
  EXPECT_NEAR(behind.passed_pct, 50.0, 1e-9);  // every hit is 2 % behind
  ComparisonMetrics front = compare_renders(load_render_outputs(ref), load_render_outputs(save(make(23, 0.98, 0, 0), "front")));
  EXPECT_EQ(front.passed_pct, 0);
  EXPECT_NE(format_json(behind).find("\"passed_pct\": 50"), std::string::npos) << format_json(behind);
}

TEST(ImageMetrics, KnownErrorsAreMeasured) {
  // Test: 3 more hit columns, depths 0.1 % long, normals tilted 2 degrees,
  // colours 51/255 = 0.2 brighter (exact in 8 bits).
  std::string ref = save(make(20, 1, 0, 0), "ref"), test = save(make(23, 1.001, 2, 0.2f), "test");
  ComparisonMetrics m = compare_renders(load_render_outputs(ref), load_render_outputs(test));
  EXPECT_NEAR(m.hit_mask_disagreement_pct, 100.0 * 3 * kH / (kW * kH), 1e-9);
  EXPECT_NEAR(m.depth_rel_error_median, 1e-3, 1e-6);  // float depths
  EXPECT_NEAR(m.depth_rel_error_p99, 1e-3, 1e-6);
  EXPECT_NEAR(m.normal_error_deg_median, 2.0, 0.01);
  EXPECT_NEAR(m.psnr_db, 10 * std::log10(1 / 0.04), 0.05);  // MSE = 0.2^2 (blue and all in range)
  EXPECT_NEAR(m.pixels_differing_pct, 100, 1e-9);  // every pixel is 51 levels off, more than 4
  EXPECT_EQ(compare_renders(load_render_outputs(ref), load_render_outputs(test), 52 / 255.0).pixels_differing_pct, 0);
  EXPECT_LT(m.ssim, 1.0);
  EXPECT_GT(m.ssim, 0.5);  // a brightness shift keeps the structure
}

// Coverage AOVs (<stem>.hit.pfm, pixel averages of several samples): the mask
// compares which side of 0.5 each pixel is on, the mean coverage difference
// every fraction, and the errors count the pixels both cover (the fully
// covered ones apart).
TEST(ImageMetrics, CoverageDecidesTheMask) {
  auto with_coverage = [](const Scene& s, const std::string& stem, auto coverage_of_column) {
    std::string png = save(s, stem);
    FloatImage hit(kW, kH, {"hit"});
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) hit.plane(0)[size_t(y) * kW + x] = coverage_of_column(x);
    write_pfm((std::filesystem::path(png).parent_path() / (stem + ".hit.pfm")).string(), hit, 0);
    return png;
  };
  // Both hit columns 0-19. The reference covers columns 0-17 fully and
  // 18-19 at 0.6 and 0.3; the test 0-16 fully, 17 at 0.5, 18-19 at 0.45, and
  // its normals are tilted 3 degrees.
  std::string ref = with_coverage(make(20, 1, 0, 0), "cov_ref", [](int x) {
    return x < 18 ? 1.0f : x == 18 ? 0.6f : x == 19 ? 0.3f : 0.0f;
  });
  std::string test = with_coverage(make(20, 1, 3, 0), "cov_test", [](int x) {
    return x < 17 ? 1.0f : x == 17 ? 0.5f : x < 20 ? 0.45f : 0.0f;
  });
  ComparisonMetrics m = compare_renders(load_render_outputs(ref), load_render_outputs(test));
  // Column 18: covered (0.6) against not (0.45); column 17 stays covered at 0.5, 19 uncovered in both.
  EXPECT_NEAR(m.hit_mask_disagreement_pct, 100.0 / kW, 1e-9);
  EXPECT_NEAR(m.holes_pct, 100.0 / kW, 1e-9);
  EXPECT_NEAR(m.coverage_diff_mean_pct, 100.0 * (0.5 + 0.15 + 0.15) / kW, 1e-4);
  EXPECT_NEAR(m.normal_error_deg_median, 3.0, 0.01);
  EXPECT_NEAR(m.normal_error_deg_median_interior, 3.0, 0.01);
  EXPECT_NE(format_json(m).find("\"coverage_diff_mean_pct\""), std::string::npos);
  EXPECT_NE(format_json(m).find("\"normal_error_deg_p99_interior\""), std::string::npos);
  EXPECT_NE(format_table(m).find("coverage difference"), std::string::npos);
  // Without hit AOVs the coverage is 0 or 1 from the depth: the same
  // renders then agree on the whole mask.
  std::filesystem::remove(std::filesystem::path(ref).parent_path() / "cov_test.hit.pfm");
  ComparisonMetrics binary = compare_renders(load_render_outputs(ref), load_render_outputs(test));
  EXPECT_NEAR(binary.hit_mask_disagreement_pct, 100.0 * 1 / kW, 1e-9);  // column 19: the reference's 0.3 is a miss
  EXPECT_NEAR(binary.coverage_diff_mean_pct, 100.0 * (0.4 + 0.7) / kW, 1e-4);
}

TEST(ImageMetrics, SsimFallsWithNoiseAndSizesMustMatch) {
  Scene a = make(20, 1, 0, 0), b = a;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> noise(-0.25f, 0.25f);
  for (int c = 0; c < 3; ++c)
    for (auto& v : b.beauty.plane(c)) v = std::clamp(v + noise(rng), 0.0f, 1.0f);
  ComparisonMetrics m = compare_renders(load_render_outputs(save(a, "clean")), load_render_outputs(save(b, "noisy")));
  EXPECT_LT(m.ssim, 0.6);
  EXPECT_LT(m.psnr_db, 20);

  Scene small;
  small.beauty = FloatImage(kW / 2, kH, {"r", "g", "b"});
  std::string p = (std::filesystem::path(::testing::TempDir()) / "metrics" / "small.png").string();
  write_png(p, small.beauty);
  EXPECT_THROW(compare_renders(load_render_outputs(save(a, "clean")), load_render_outputs(p)), std::invalid_argument);
}

TEST(ImageMetrics, WithoutAovsOnlyImageErrorsAreReported) {
  Scene a = make(20, 1, 0, 0);
  std::string p = (std::filesystem::path(::testing::TempDir()) / "metrics" / "plain.png").string();
  std::filesystem::create_directories(std::filesystem::path(p).parent_path());
  write_png(p, a.beauty);
  ComparisonMetrics m = compare_renders(load_render_outputs(p), load_render_outputs(p));
  EXPECT_FALSE(m.has_depth);
  EXPECT_NE(format_table(m).find("no depth AOVs"), std::string::npos);
}

}  // namespace
}  // namespace sdfrt
