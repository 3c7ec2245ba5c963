// render.normals: dual against central differences on smooth primitives:
// the forward-mode gradient and a fine 6-tap central difference of the same
// kernel's scene_dist must agree within 0.5 degrees at surface points; and a
// scene with a node that has no dual derivatives is a clear scene error.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <algorithm>
#include <random>

#include "sdfc/support/diagnostics.hpp"
#include "normal_probe.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc {
namespace {

using test::V3;

const char* kScene =
    "render: {normals: dual}\n"
    "scene:\n"
    "  union:\n"
    "    - {sphere: {radius: 0.8}}\n"
    "    - {torus: {major_radius: 0.7, minor_radius: 0.2}, rotate: {axis: [1, 0.5, 0], degrees: 35}, translate: [3, 0, 0]}\n"
    "    - {capsule: {a: [0, 0, -0.5], b: [0.3, 0.2, 0.6], radius: 0.3}, scale: 1.3, translate: [-3, 0, 0]}\n"
    "    - {cylinder: {radius: 0.5, height: 1.2}, rotate: [20, 10, 0], translate: [0, 3, 0]}\n"
    "    - {difference: [{sphere: {radius: 0.7}}, {sphere: {radius: 0.4}, translate: [0.6, 0, 0]}], translate: [0, -3, 0]}\n"
    "    - {smooth_union: {radius: 0.3, children: [{sphere: {radius: 0.5}}, {box: {size: [0.6, 0.6, 1.4]}, translate: [0.5, 0, 0]}]},\n"
    "       translate: [3, 3, 0]}\n"
    "    - {smooth_difference: {radius: 0.2, children: [{box: {size: [1, 1, 1], radius: 0.1}}, {sphere: {radius: 0.5}, translate: [0.4, 0.4, 0.4]}]},\n"
    "       translate: [-3, 3, 0]}\n"
    "    - {smooth_intersection: {radius: 0.2, children: [{sphere: {radius: 0.6}}, {cylinder: {radius: 0.4, height: 2}}]}, translate: [-3, -3, 0]}\n";

class DualNormals : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(DualNormals, AgreeWithCentralDifferences) {
  auto [width, dbl] = GetParam();
  ir::Module m = test::compile_text(kScene, "dual.yaml", {std::string("render.precision=") + (dbl ? "double" : "float")});
  std::mt19937_64 rng(11);
  auto f = [&](const V3& p) { return reference::distance(m, p); };
  std::vector<V3> pts = test::surface_points(f, {-4, -4, -1.5}, {4, 4, 1.5}, 400, rng);
  ASSERT_GE(pts.size(), 300u);
  std::vector<float> out = test::run_point_kernel(normal_kernel(m, width), "normal_probe", pts, width);
  double worst = 0;
  for (size_t i = 0; i < pts.size(); ++i)
    worst = std::max(worst, std::acos(std::clamp(double(out[i]), -1.0, 1.0)) * 180 / std::numbers::pi);
  fmt::print("[dual-normals] w{} {}: {} surface points, largest angle to central differences {:.4f} deg\n", width,
             dbl ? "double" : "float", pts.size(), worst);
  EXPECT_LT(worst, 0.5);
}

INSTANTIATE_TEST_SUITE_P(Widths, DualNormals, ::testing::Combine(::testing::Values(1, 8), ::testing::Bool()),
                         [](const auto& info) {
                           return fmt::format("w{}_{}", std::get<0>(info.param), std::get<1>(info.param) ? "double" : "float");
                         });

TEST(DualNormalsErrors, FractalWithoutDualDerivativesIsASceneError) {
  try {
    test::compile_text("render: {normals: dual}\nscene: {union: [{sphere: {}}, {menger: {}}]}\n");
    FAIL() << "expected a scene error";
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("1:19"), std::string::npos) << what;
    EXPECT_NE(what.find("'menger' (line 2) does not have"), std::string::npos) << what;
    EXPECT_NE(what.find("they exist for sphere, box"), std::string::npos) << what;
    EXPECT_NE(what.find("mandelbulb (and its julia form), mandelbox, julia"), std::string::npos) << what;
  }
}

// Fractals with a running Jacobian: the dual normal is the gradient of the
// estimator by dual numbers through the orbit (the Jacobian of z and the
// gradient of the running derivative). At the hits of rays (where the
// renderer shades) it must agree with central differences at most points;
// they can differ where the escape step changes within the difference's reach.
const char* kFractalScene =
    "render: {normals: dual}\n"
    "scene:\n"
    "  union:\n"
    "    - {mandelbulb: {power: 8, iterations: 8}}\n"
    "    - {mandelbulb: {power: 8, iterations: 8, julia: [0.35, -0.3, 0.2]}, translate: [3, 0, 0]}\n"
    "    - {mandelbox: {scale: -1.5, iterations: 12}, scale: 0.25, translate: [0, 3, 0]}\n"
    "    - {julia: {c: [-0.2, 0.6, 0.2, 0.2], iterations: 12}, translate: [3, 3, 0]}\n"
    "    - {julia: {c: [-0.4, 0.3, 0.2, 0.1], degree: 3, iterations: 10}, translate: [-3, 0, 0]}\n";

TEST(DualNormalsFractals, AgreeWithCentralDifferencesAtMostHits) {
  ir::Module m = test::compile_text(kFractalScene, "dual_fractals.yaml", {"render.precision=double"});
  std::mt19937_64 rng(5);
  const std::vector<V3> centres = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {3, 3, 0}, {-3, 0, 0}};
  const char* names[] = {"mandelbulb", "juliabulb", "mandelbox", "julia", "julia cubic"};
  const int width = 8;
  for (size_t c = 0; c < centres.size(); ++c) {
    std::vector<V3> pts;
    for (int attempt = 0; attempt < 600 && pts.size() < 300; ++attempt) {
      auto [o, rd] = test::random_ray(rng, centres[c], 1.4, 0.3);
      auto f = [&](const V3& x) { return reference::distance(m, x); };
      if (auto t = test::trace_to_surface(f, o, rd, 2e-4, 3)) pts.push_back(test::add(o, test::mul(rd, *t)));
    }
    ASSERT_GE(pts.size(), 200u) << names[c];
    // In double, a central difference 2000x finer than the hit distance: the
    // estimator's own gradient there, not an average over its detail (at
    // h = 1e-5 the 12-step Mandelbox's detail already bends it by 2 degrees
    // at the median).
    std::vector<float> out = test::run_point_kernel(normal_kernel(m, width, "1e-7"), "normal_probe", pts, width);
    std::vector<double> angle;
    for (size_t i = 0; i < pts.size(); ++i)
      angle.push_back(std::acos(std::clamp(double(out[i]), -1.0, 1.0)) * 180 / std::numbers::pi);
    std::sort(angle.begin(), angle.end());
    int within = int(std::lower_bound(angle.begin(), angle.end(), 1.0) - angle.begin());
    fmt::print("[dual-normals] {:<11}: {} hits, median angle to central differences {:.4f} deg, {:.1f} % within 1 deg\n",
               names[c], pts.size(), angle[angle.size() / 2], 100.0 * within / pts.size());
    EXPECT_LT(angle[angle.size() / 2], 0.1) << names[c];
    EXPECT_GE(within, int(0.95 * pts.size())) << names[c];
  }
}

}  // namespace
}  // namespace sdfc
