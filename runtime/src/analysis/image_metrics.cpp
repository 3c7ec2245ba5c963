#include <fmt/format.h>
#include <sdfrt/image_metrics.hpp>
#include <sdfrt/image_read.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sdfrt {

namespace {

// The q-quantile by nearest rank; 0 for an empty set.
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  size_t k = std::min(v.size() - 1, size_t(std::ceil(q * double(v.size()))) - (q > 0 ? 1 : 0));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

std::vector<double> luma(const FloatImage& img) {
  std::vector<double> y(img.plane_size());
  auto r = img.plane(0), g = img.plane(1), b = img.plane(2);
  for (size_t i = 0; i < y.size(); ++i) y[i] = 0.2126 * r[i] + 0.7152 * g[i] + 0.0722 * b[i];
  return y;
}

// Mean SSIM (Wang et al. 2004) over 7x7 windows, dynamic range 1, computed
// with summed-area tables so it stays linear in the pixel count.
double ssim(const FloatImage& a, const FloatImage& b) {
  const int w = a.width, h = a.height, win = 7;
  if (w < win || h < win) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> x = luma(a), y = luma(b);
  auto table = [&](auto f) {
    std::vector<double> s(size_t(w + 1) * (h + 1), 0.0);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        s[size_t(j + 1) * (w + 1) + i + 1] = f(size_t(j) * w + i) + s[size_t(j) * (w + 1) + i + 1] +
                                             s[size_t(j + 1) * (w + 1) + i] - s[size_t(j) * (w + 1) + i];
    return s;
  };
  auto sx = table([&](size_t i) { return x[i]; }), sy = table([&](size_t i) { return y[i]; });
  auto sxx = table([&](size_t i) { return x[i] * x[i]; }), syy = table([&](size_t i) { return y[i] * y[i]; });
  auto sxy = table([&](size_t i) { return x[i] * y[i]; });
  auto box = [&](const std::vector<double>& s, int i, int j) {
    return s[size_t(j + win) * (w + 1) + i + win] - s[size_t(j) * (w + 1) + i + win] - s[size_t(j + win) * (w + 1) + i] +
           s[size_t(j) * (w + 1) + i];
  };
  const double n = win * win, c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  double total = 0;
  long count = 0;
  for (int j = 0; j + win <= h; ++j)
    for (int i = 0; i + win <= w; ++i) {
      double mx = box(sx, i, j) / n, my = box(sy, i, j) / n;
      // Sample (co)variances, as the reference implementation uses.
      double vx = (box(sxx, i, j) - n * mx * mx) / (n - 1), vy = (box(syy, i, j) - n * my * my) / (n - 1);
      double cxy = (box(sxy, i, j) - n * mx * my) / (n - 1);
      total += ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++count;
    }
  return total / double(count);
}

}  // namespace

RenderOutputs load_render_outputs(const std::string& png_path) {
  RenderOutputs o;
  o.path = png_path;
  o.beauty = read_png(png_path);
  std::filesystem::path p(png_path);
  auto beside = [&](const char* aov) { return (p.parent_path() / (p.stem().string() + "." + aov + ".pfm")).string(); };
  if (std::filesystem::exists(beside("depth"))) o.depth = read_pfm(beside("depth"), "depth");
  if (std::filesystem::exists(beside("normal"))) o.normal = read_pfm(beside("normal"), "normal");
  if (std::filesystem::exists(beside("hit"))) o.hit = read_pfm(beside("hit"), "hit");
  return o;
}

ComparisonMetrics compare_renders(const RenderOutputs& ref, const RenderOutputs& test, double pixel_threshold) {
  const FloatImage &a = ref.beauty, &b = test.beauty;
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument(fmt::format("the renders differ in size: {}x{} and {}x{}", a.width, a.height, b.width,
                                            b.height));
  ComparisonMetrics m;
  m.width = a.width, m.height = a.height;
  const size_t n = a.plane_size();

  double se = 0;
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < n; ++i) {
      double d = double(a.plane(c)[i]) - double(b.plane(c)[i]);
      se += d * d;
    }
  double mse = se / double(3 * n);
  size_t differing = 0;
  for (size_t i = 0; i < n; ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) differs |= std::fabs(double(a.plane(c)[i]) - double(b.plane(c)[i])) > pixel_threshold;
    differing += differs;
  }
  m.pixel_threshold = pixel_threshold;
  m.pixels_differing_pct = n ? 100.0 * double(differing) / double(n) : 0.0;
  m.psnr_db = mse > 0 ? 10 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  m.ssim = ssim(a, b);

  m.has_depth = ref.depth && test.depth;
  if (m.has_depth) {
    auto da = ref.depth->plane(0), db = test.depth->plane(0);
    if (ref.depth->width != a.width || test.depth->width != b.width || ref.depth->height != a.height ||
        test.depth->height != b.height)
      throw std::invalid_argument("a depth AOV does not match its image's size");
    m.has_normal = ref.normal && test.normal;
    auto coverage = [](const RenderOutputs& o, const FloatImage& img) {
      std::vector<double> c(img.plane_size());
      if (o.hit) {
        if (o.hit->width != img.width || o.hit->height != img.height)
          throw std::invalid_argument("a hit AOV does not match its image's size");
        for (size_t i = 0; i < c.size(); ++i) c[i] = std::clamp(double(o.hit->plane(0)[i]), 0.0, 1.0);
      } else {
        for (size_t i = 0; i < c.size(); ++i) c[i] = o.depth->plane(0)[i] >= 0 ? 1.0 : 0.0;
      }
      return c;
    };
    for (size_t i = 0; i < n; ++i)  // a NaN depth would count as a miss and hide the error
      if (std::isnan(da[i]) || std::isnan(db[i]))
        throw std::invalid_argument(fmt::format("a depth AOV holds NaN (pixel {}, {}); it is not a valid render",
                                                i % size_t(a.width), i / size_t(a.width)));
    const std::vector<double> ca = coverage(ref, a), cb = coverage(test, b);
    size_t disagree = 0, holes = 0, passed = 0;
    double coverage_diff = 0;
    std::vector<double> depth_err, normal_err, normal_err_interior;
    for (size_t i = 0; i < n; ++i) {
      coverage_diff += std::fabs(ca[i] - cb[i]);
      // depth < 0: no sample hit (a hand-made AOV set could disagree with hit)
      bool ha = ca[i] >= kCoveredFraction && da[i] >= 0, hb = cb[i] >= kCoveredFraction && db[i] >= 0;
      if (ha != hb) ++disagree;
      if (ha && !hb) ++holes, ++passed;
      if (!(ha && hb)) continue;
      if (double(db[i]) > 1.01 * double(da[i])) ++passed;
      depth_err.push_back(std::fabs(double(db[i]) - double(da[i])) / std::max(double(da[i]), 1e-12));
      if (m.has_normal) {
        // atan2(|a x b|, a . b): exact for equal normals, where acos of a
        // rounded dot product gave 0.03 degrees between a file and itself.
        double u[3], v[3];
        for (int c = 0; c < 3; ++c) u[c] = ref.normal->plane(c)[i], v[c] = test.normal->plane(c)[i];
        const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
        const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        normal_err.push_back(std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) * 180.0 / M_PI);
        if (ca[i] >= 1.0) normal_err_interior.push_back(normal_err.back());
      }
    }
    m.coverage_diff_mean_pct = n ? 100.0 * coverage_diff / double(n) : 0.0;
    // NaN (null in JSON) when the reference covers no pixel fully (a sparse fractal)
    const double none = std::numeric_limits<double>::quiet_NaN();
    m.normal_error_deg_median_interior = normal_err_interior.empty() ? none : quantile(normal_err_interior, 0.5);
    m.normal_error_deg_p99_interior = normal_err_interior.empty() ? none : quantile(normal_err_interior, 0.99);
    m.hit_mask_disagreement_pct = 100.0 * double(disagree) / double(n);
    m.holes_pct = 100.0 * double(holes) / double(n);
    m.passed_pct = 100.0 * double(passed) / double(n);
    m.depth_rel_error_median = quantile(depth_err, 0.5);
    m.depth_rel_error_p99 = quantile(depth_err, 0.99);
    m.normal_error_deg_median = quantile(normal_err, 0.5);
    m.normal_error_deg_p99 = quantile(normal_err, 0.99);
  }
  return m;
}

std::string format_table(const ComparisonMetrics& m) {
  std::string s = fmt::format("{:<32} {}\n", "size", fmt::format("{}x{}", m.width, m.height));
  if (m.has_depth) {
    s += fmt::format("{:<32} {:.4f} %\n", "hit-mask disagreement", m.hit_mask_disagreement_pct);
    s += fmt::format("{:<32} {:.4f} %\n", "coverage difference, mean", m.coverage_diff_mean_pct);
    s += fmt::format("{:<32} {:.4f} %\n", "holes (reference hits only)", m.holes_pct);
    s += fmt::format("{:<32} {:.4f} %\n", "passed the reference surface", m.passed_pct);
    s += fmt::format("{:<32} {:.3e} / {:.3e}\n", "depth error, median / p99", m.depth_rel_error_median, m.depth_rel_error_p99);
  } else {
    s += fmt::format("{:<32} {}\n", "hit mask, depth", "no depth AOVs (render with --aov depth,normal,hit)");
  }
  if (m.has_normal) {
    s += fmt::format("{:<32} {:.3f} / {:.3f} deg\n", "normal error, median / p99", m.normal_error_deg_median,
                     m.normal_error_deg_p99);
    if (std::isnan(m.normal_error_deg_p99_interior))
      s += fmt::format("{:<32} {}\n", "  where the reference covers all", "no pixel is fully covered");
    else
      s += fmt::format("{:<32} {:.3f} / {:.3f} deg\n", "  where the reference covers all", m.normal_error_deg_median_interior,
                       m.normal_error_deg_p99_interior);
  }
  s += fmt::format("{:<32} {:.4f} %\n", fmt::format("pixels differing > {:.1f}/255", m.pixel_threshold * 255),
                   m.pixels_differing_pct);
  s += fmt::format("{:<32} {:.2f} dB\n", "PSNR", m.psnr_db);
  s += fmt::format("{:<32} {:.5f}\n", "SSIM", m.ssim);
  return s;
}

std::string format_json(const ComparisonMetrics& m) {
  auto num = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string("null"); };
  std::string s = fmt::format("{{\"width\": {}, \"height\": {}, \"psnr_db\": {}, \"ssim\": {}", m.width, m.height,
                              num(m.psnr_db), num(m.ssim));
  s += fmt::format(", \"pixel_threshold\": {}, \"pixels_differing_pct\": {}", num(m.pixel_threshold),
                   num(m.pixels_differing_pct));
  if (m.has_depth)
    s += fmt::format(", \"hit_mask_disagreement_pct\": {}, \"depth_rel_error_median\": {}, \"depth_rel_error_p99\": {}",
                     num(m.hit_mask_disagreement_pct), num(m.depth_rel_error_median), num(m.depth_rel_error_p99));
  if (m.has_depth)
    s += fmt::format(", \"coverage_diff_mean_pct\": {}, \"holes_pct\": {}, \"passed_pct\": {}",
                     num(m.coverage_diff_mean_pct), num(m.holes_pct), num(m.passed_pct));
  if (m.has_normal)
    s += fmt::format(", \"normal_error_deg_median\": {}, \"normal_error_deg_p99\": {}, "
                     "\"normal_error_deg_median_interior\": {}, \"normal_error_deg_p99_interior\": {}",
                     num(m.normal_error_deg_median), num(m.normal_error_deg_p99),
                     num(m.normal_error_deg_median_interior), num(m.normal_error_deg_p99_interior));
  return s + "}\n";
}

}  // namespace sdfrt
