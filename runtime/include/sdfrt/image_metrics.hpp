#pragma once
// Error metrics of a render against a reference render of the same view:
// hit-mask disagreement, depth and normal errors (from the AOVs) and image
// error (PSNR, SSIM). Used by `sdfc compare` and the accuracy benchmark.
#include <sdfrt/float_image.hpp>

#include <optional>
#include <string>

namespace sdfrt {

// A render as written by `sdfc render --aov depth,normal,hit`: the beauty
// image and, when present beside it, <stem>.depth.pfm, <stem>.normal.pfm and
// <stem>.hit.pfm. With several samples per pixel the AOVs are pixel
// averages (depth and normal over the samples that hit).
struct RenderOutputs {
  std::string path;
  FloatImage beauty;                 // planes r, g, b in [0, 1]
  std::optional<FloatImage> depth;   // plane "depth": ray distance, -1 on a miss
  std::optional<FloatImage> normal;  // planes normal.x/y/z, 0 on a miss
  std::optional<FloatImage> hit;     // plane "hit": coverage in [0, 1]; absent: depth >= 0
};
RenderOutputs load_render_outputs(const std::string& png_path);

// A pixel counts as covered (a hit) when its coverage is at least this.
constexpr double kCoveredFraction = 0.5;

struct ComparisonMetrics {
  int width = 0, height = 0;
  bool has_depth = false, has_normal = false;
  // Pixels one covers (coverage >= 0.5) and the other does not; with one
  // sample per pixel: one hits, the other misses.
  double hit_mask_disagreement_pct = 0;
  double coverage_diff_mean_pct = 0;  // mean |coverage - coverage_ref|, in % of a pixel
  double holes_pct = 0;   // the reference covers, the test does not (a hole in the test)
  // The test passed the reference's surface: a hole, or a hit more than 1 %
  // of the distance behind the reference's (overshoot; a lower-bound march
  // with a larger hit epsilon stops in front, never behind).
  double passed_pct = 0;
  // Over the pixels both cover; depth and normal are pixel means over the
  // samples that hit.
  double depth_rel_error_median = 0, depth_rel_error_p99 = 0;  // |d - d_ref| / d_ref
  double normal_error_deg_median = 0, normal_error_deg_p99 = 0;  // angle
  // The same over the pixels the reference covers fully (coverage 1) and
  // the test covers: no silhouette or pore inside the pixel (NaN if none).
  double normal_error_deg_median_interior = 0, normal_error_deg_p99_interior = 0;
  // Pixels where some display-encoded channel differs by more than
  // pixel_threshold (in [0, 1]; the default 4/255 is 4 levels of an 8-bit PNG,
  // above the rounding noise of float against double arithmetic).
  double pixel_threshold = 0;
  double pixels_differing_pct = 0;
  double psnr_db = 0;  // of the display-encoded RGB; +inf for identical images
  double ssim = 0;     // mean SSIM of the luma, 7x7 windows
};

constexpr double kDefaultPixelThreshold = 4.0 / 255.0;

// Throws std::invalid_argument when the sizes differ.
ComparisonMetrics compare_renders(const RenderOutputs& reference, const RenderOutputs& test,
                                  double pixel_threshold = kDefaultPixelThreshold);
std::string format_table(const ComparisonMetrics& m);
std::string format_json(const ComparisonMetrics& m);

}  // namespace sdfrt
