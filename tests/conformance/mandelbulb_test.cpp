// The Mandelbulb distance estimator on every OpenCL evaluator against the CPU
// reference: >= 1500 points in [-1.5, 1.5]^3, points along rays through the
// surface, and far points (the far-field branch).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "conformance.hpp"
#include "sdfc/ir/fractal_math.hpp"

namespace sdfc::conformance {
namespace {

using test::add;
using test::mul;
using test::norm;

struct BulbScene {
  std::string name;
  std::string yaml;
};

void PrintTo(const BulbScene& s, std::ostream* os) { *os << s.name; }

std::vector<BulbScene> bulb_scenes() {
  return {{"power8", "scene: {mandelbulb: {power: 8, iterations: 10, bailout: 2}}\n"},
          {"power3", "scene: {mandelbulb: {power: 3, iterations: 10, bailout: 2}}\n"},
          {"power8_transformed",
           "scene: {mandelbulb: {power: 8, iterations: 10, bailout: 2}, scale: 0.7, "
           "rotate: {axis: [0, 1, 1], degrees: 25}, translate: [0.3, -0.2, 0.1]}\n"}};
}

// Tolerance for the estimator.
//
// float, outside the set (d >= 0): the orbit runs through pow, acos, atan2,
//   sin and cos in float for up to 10 iterations, each multiplying the
//   orbit's relative error by about the power (z -> z^n), so float and double
//   orbits drift apart by up to ~1e-4 relative before the estimate
//   0.5 log(r) r / dr is formed. The estimate is smooth in the escaped orbit
//   (it barely depends on which iteration it bails out at), so the error stays
//   proportional to |d|: 2e-3 |d| + 2e-4. Observed over 200k random points:
//   at most 19% of this (power 8), 1.4% (power 3); a changed constant (power,
//   bailout, set radius) moves d by far more.
// float, inside the set (d < 0): the orbit never escapes, and near the z axis
//   acos(z / r) is ill-conditioned (d theta = dz / sqrt(1 - z^2/r^2)), so the
//   float orbit decorrelates from the double one and only the sign and rough
//   size of the interior value are reproducible (the marcher only uses it to
//   stop). Observed: up to ~2.5e-3 absolute, 3x relative for |d| ~ 1e-3, on
//   power 8 near the poles. We allow 5e-3 + 0.5 |d| there.
// double: the probe stores floats, so the double kernel can only match to
//   the float rounding of its result (1 ulp, 2^-23 |d|), not the ~1e-9 a
//   double-to-double comparison would allow. Observed: within half an ulp
//   everywhere, inside included, over 200k points.
Tolerance bulb_tolerance(bool dbl) { return dbl ? Tolerance{1e-9, 0x1p-23} : Tolerance{2e-4, 2e-3, 5e-3, 0.5}; }

std::vector<V3> bulb_points(const ir::Module& m, const std::string& seed) {
  std::mt19937_64 rng(std::hash<std::string>{}(seed) ^ 0xb01b);
  std::vector<V3> pts;
  for (int i = 0; i < 1500; ++i) pts.push_back(test::uniform_in(rng, {-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}));
  // Rays from outside towards (near) the centre: march the reference to the
  // surface, then sample densely across it (outside and inside).
  int rays = 0;
  for (int attempt = 0; attempt < 40 && rays < 10; ++attempt) {
    V3 dir = test::random_unit(rng);
    V3 o = mul(dir, -2.5);
    V3 aim = mul(test::random_unit(rng), 0.2);
    V3 rd = test::normalize(test::sub(aim, o));
    auto t = test::trace_to_surface([&](const V3& x) { return reference::distance(m, x); }, o, rd, 1e-6, 6, 2000);
    if (!t) continue;
    ++rays;
    for (int k = -60; k <= 60; ++k) pts.push_back(add(o, mul(rd, *t + k * 5e-4)));
  }
  // The far field (beyond 1.5x the set radius the estimator returns the
  // distance to the bounding ball).
  std::uniform_real_distribution<double> far(2.0, 10.0);
  for (int i = 0; i < 100; ++i) pts.push_back(mul(test::random_unit(rng), far(rng)));
  return pts;
}

class MandelbulbConformance : public ::testing::TestWithParam<std::tuple<BulbScene, EvalConfig>> {};

TEST_P(MandelbulbConformance, MatchesReference) {
  const auto& [sc, cfg] = GetParam();
  ir::Module m = test::compile_text(sc.yaml, sc.name + ".yaml", cfg.overrides());
  std::vector<V3> pts = bulb_points(m, sc.name);
  ASSERT_GE(pts.size(), 2000u) << "too few rays found the surface";
  ProbeCheck pc = probe_and_compare(m, cfg, pts, bulb_tolerance(cfg.dbl));

  // The points must exercise both sides and the near surface, or the
  // comparison says little.
  int inside = 0, near = 0;
  for (double d : pc.ref_d) inside += d < 0, near += std::fabs(d) < 1e-2;
  EXPECT_GT(inside, 20);
  EXPECT_GT(near, 500);
  expect_inside_bounds(m, pc.points);
}

INSTANTIATE_TEST_SUITE_P(Mandelbulb, MandelbulbConformance,
                         ::testing::Combine(::testing::ValuesIn(bulb_scenes()), ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) { return std::get<0>(info.param).name + "_" + std::get<1>(info.param).name(); });

// Sanity of the oracle's far field: beyond 1.5x the radius of the ball that
// holds the set, the reference is the distance to that ball (a true lower
// bound), and that radius is what the estimator's header promises.
TEST(MandelbulbOracle, FarFieldIsDistanceToTheBoundingBall) {
  for (double power : {3.0, 8.0}) {
    ir::Module m = test::compile_text(fmt::format("scene: {{mandelbulb: {{power: {}, iterations: 10, bailout: 2}}}}\n", power));
    double R = ir::mandelbulb_set_radius(power);
    EXPECT_NEAR(R, std::pow(2.0, 1.0 / (power - 1.0)), 1e-15);
    std::mt19937_64 rng(42);
    for (int i = 0; i < 200; ++i) {
      V3 p = mul(test::random_unit(rng), 1.5 * R + 0.01 + i * 0.05);
      // The estimator's own far field, not the bounding box the passes put around it.
      ir::NodeId bulb = ir::kNoNode;
      for (ir::NodeId id : m.graph->postorder(m.root))
        if (m.graph->node(id).kind == ir::Kind::Mandelbulb) bulb = id;
      EXPECT_NEAR(reference::evaluate(*m.graph, bulb, p).distance, norm(p) - R, 1e-12);
    }
  }
}

}  // namespace
}  // namespace sdfc::conformance
