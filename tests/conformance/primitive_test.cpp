// Primitives, alone and under a transform chain:
//  - every OpenCL evaluator (SIMD width x precision) against the CPU
//    reference, on >= 1000 points per scene (PrimitiveConformance);
//  - the reference itself (the oracle) against the textbook distance and a
//    brute-force distance to a dense parametric sampling of the surface
//    (PrimitiveOracle).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "conformance.hpp"
#include "primitives.hpp"

namespace sdfc::conformance {
namespace {

using test::add;
using test::mul;
using test::norm;
using test::sub;

// Test points for one scene, fixed seed per scene: uniform in a box `pad` x the
// shape (inside, near and outside), points on the surface, and far points.
std::vector<V3> scene_points(const PrimitiveScene& sc, size_t uniform, size_t surface, size_t far,
                             double pad = 1.4) {
  std::mt19937_64 rng(std::hash<std::string>{}(sc.name()) ^ 0x5dfc);
  V3 lo, hi;
  sc.world_box(pad, lo, hi);
  std::vector<V3> pts;
  for (size_t i = 0; i < uniform; ++i) pts.push_back(test::uniform_in(rng, lo, hi));
  SurfaceSamples s = sc.world_surface(0.05);
  std::uniform_int_distribution<size_t> pick(0, s.points.size() - 1);
  for (size_t i = 0; i < surface; ++i) pts.push_back(s.points[pick(rng)]);
  V3 centre = mul(add(lo, hi), 0.5);
  std::uniform_real_distribution<double> dist(5.0, 40.0);
  for (size_t i = 0; i < far; ++i) pts.push_back(add(centre, mul(test::random_unit(rng), dist(rng))));
  return pts;
}

std::string scene_name(const PrimitiveScene& s) { return s.name(); }

// ---- every evaluator against the reference ---------------------------------

class PrimitiveConformance : public ::testing::TestWithParam<std::tuple<PrimitiveScene, EvalConfig>> {};

TEST_P(PrimitiveConformance, MatchesReference) {
  const auto& [sc, cfg] = GetParam();
  ir::Module m = test::compile_text(sc.yaml(), sc.name() + ".yaml", cfg.overrides());
  ASSERT_EQ(m.plan.march.precision, cfg.dbl ? ir::Precision::Double : ir::Precision::Float);
  std::vector<V3> pts = scene_points(sc, 800, 300, 150);
  ProbeCheck pc = probe_and_compare(m, cfg, pts, kernel_tolerance(cfg.dbl));

  // The material is constant over a lone primitive: 0 without one, the
  // innermost (m1 = 1) under the chain. Check the reference agrees too.
  // (Ids are renumbered densely by eliminate_dead, so compare names.)
  int wrong = 0;
  for (int mat : pc.ref_mat) wrong += m.plan.materials.at(mat).name != sc.material();
  EXPECT_EQ(wrong, 0) << "reference material differs from " << sc.material();

  // The kernel also against the textbook distance (not only the oracle):
  // the same float tolerance plus the reference-vs-textbook slack.
  Tolerance tol = kernel_tolerance(cfg.dbl);
  int bad = 0;
  for (size_t i = 0; i < pc.points.size(); ++i) {
    double exact = sc.exact(pc.points[i]);
    if (!(std::fabs(pc.got.d[i] - exact) <= tol.allowed(exact) + 1e-9)) ++bad;
  }
  EXPECT_EQ(bad, 0) << bad << " kernel distances differ from the textbook distance";
}

INSTANTIATE_TEST_SUITE_P(Primitives, PrimitiveConformance,
                         ::testing::Combine(::testing::ValuesIn(primitive_scenes()),
                                            ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) {
                           return scene_name(std::get<0>(info.param)) + "_" + std::get<1>(info.param).name();
                         });

// ---- the oracle: reference vs textbook and brute force ---------------------

class PrimitiveOracle : public ::testing::TestWithParam<PrimitiveScene> {};

// The reference (after the whole pass pipeline: transform folding and
// pushing, material ordering) against the textbook distance computed here
// from the YAML's own numbers with an independent (quaternion) rotation.
// Both are double; they differ only by rounding (~1e-16 relative on values
// of magnitude <= 50), so 1e-10 absolute is generous and still catches any
// wrong constant, axis convention or transform order.
TEST_P(PrimitiveOracle, ReferenceMatchesTextbookDistance) {
  const PrimitiveScene& sc = GetParam();
  ir::Module m = test::compile_text(sc.yaml(), sc.name() + ".yaml");
  std::vector<V3> pts = scene_points(sc, 3000, 500, 200);
  int bad = 0;
  std::string msgs;
  for (const auto& p : pts) {
    double ref = reference::distance(m, p), ex = sc.exact(p);
    if (!(std::fabs(ref - ex) <= 1e-10 + 1e-12 * std::fabs(ex)) && bad++ < 5)
      msgs += fmt::format("  at ({:.9g}, {:.9g}, {:.9g}): reference {:.15g}, textbook {:.15g}\n", p[0], p[1], p[2], ref, ex);
  }
  EXPECT_EQ(bad, 0) << msgs;

  // Points sampled on the surface (parametrically, no SDF involved) are at distance 0.
  SurfaceSamples s = sc.world_surface(0.05);
  double worst = 0;
  for (const auto& p : s.points) worst = std::max(worst, std::fabs(reference::distance(m, p)));
  EXPECT_LT(worst, 1e-9) << "surface samples are not on the reference's zero set";

  expect_inside_bounds(m, pts);
}

// Brute force: the distance to the nearest of a dense set of surface
// samples. Since the samples lie on the surface, the true distance can never
// exceed it; since every surface point is within `covering` of a sample (half
// the largest cell diagonal of the sampling grid, ~0.015 here), it exceeds
// the true distance by at most `covering`. Checked for points inside (|d|)
// and outside.
TEST_P(PrimitiveOracle, ReferenceMatchesBruteForceDistance) {
  const PrimitiveScene& sc = GetParam();
  ir::Module m = test::compile_text(sc.yaml(), sc.name() + ".yaml");
  SurfaceSamples s = sc.world_surface(0.02);
  ASSERT_GT(s.points.size(), 1000u);
  ASSERT_LT(s.covering, 0.05);
  std::vector<V3> pts = scene_points(sc, 600, 0, 0, 1.2);
  int over = 0, under = 0, outside = 0;
  std::string msgs;
  for (const auto& p : pts) {
    double ref = reference::distance(m, p);
    outside += ref > 0;
    double bf = 1e300;
    for (const auto& q : s.points) {
      V3 d = sub(p, q);
      bf = std::min(bf, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    bf = std::sqrt(bf);
    if (std::fabs(ref) > bf + 1e-9 && over++ < 5)
      msgs += fmt::format("  at ({:.6g}, {:.6g}, {:.6g}): |reference| {:.9g} > brute force {:.9g}\n", p[0], p[1], p[2],
                          std::fabs(ref), bf);
    if (bf > std::fabs(ref) + s.covering && under++ < 5)
      msgs += fmt::format("  at ({:.6g}, {:.6g}, {:.6g}): brute force {:.9g} > |reference| {:.9g} + covering {:.4g}\n",
                          p[0], p[1], p[2], bf, std::fabs(ref), s.covering);
  }
  EXPECT_EQ(over + under, 0) << msgs;
  EXPECT_GT(outside, 50) << "too few outside points to mean anything";
  EXPECT_GT(int(pts.size()) - outside, 10) << "too few inside points to mean anything";
}

INSTANTIATE_TEST_SUITE_P(Primitives, PrimitiveOracle, ::testing::ValuesIn(primitive_scenes()),
                         [](const auto& info) { return scene_name(info.param); });

}  // namespace
}  // namespace sdfc::conformance
