// Conformance driven by the kind table: every described kind, from its
// example, without a line of test code per kind.
//  - KindTableConformance: every OpenCL evaluator (SIMD width x precision)
//    against the double reference, distance and material, on points in
//    and around each example (the bounded kinds share one kernel);
//  - KindTableOracle: each kind's reference distance against brute force:
//    the distance to a dense sampling of the surface (found from the sign
//    alone), equal for an exact kind, never exceeded for a bound;
//  - KindTableDualNormals: the kinds that claim dual normals, against
//    central differences;
//  - KindTableScenes: every described kind has a scene.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "conformance.hpp"
#include "kind_scenes.hpp"
#include "normal_probe.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::conformance {
namespace {

using test::add;
using test::mul;
using test::norm;
using test::sub;

TEST(KindTableScenes, EveryDescribedKindHasAScene) {
  std::set<const kinds::Description*> seen;
  for (const KindScene& s : kind_scenes())
    for (const KindCell& c : s.cells) EXPECT_TRUE(seen.insert(c.kind).second) << c.kind->yaml << " is in two scenes";
  for (const kinds::Description* d : kinds::all())
    EXPECT_TRUE(seen.count(d)) << d->yaml << " is described but has no conformance scene";
  // And the compiled scenes really hold each kind (the passes kept it).
  for (const KindScene& s : kind_scenes()) {
    ir::Module m = test::compile_text(s.yaml, s.name + ".yaml");
    std::set<ir::Kind> kinds;
    for (ir::NodeId id : m.graph->postorder(m.root)) kinds.insert(m.graph->node(id).kind);
    for (const KindCell& c : s.cells) {
      if (ir::info(c.kind->kind).category == ir::Category::Primitive) {
        EXPECT_TRUE(kinds.count(c.kind->kind)) << s.name << " lost its " << c.kind->yaml;
      }
    }
  }
}

// Points for one cell: uniform in its bounds grown by half, and on its surface.
std::vector<V3> cell_points(const ir::Module& m, const KindCell& c, std::mt19937_64& rng) {
  V3 mid = mul(add(c.lo, c.hi), 0.5), half = mul(sub(c.hi, c.lo), 0.75);
  for (double& h : half) h = std::max(h, 0.2);
  V3 lo = sub(mid, half), hi = add(mid, half);
  std::vector<V3> pts;
  for (int i = 0; i < 160; ++i) pts.push_back(test::uniform_in(rng, lo, hi));
  auto f = [&](const V3& p) { return reference::distance(m, p); };
  for (const V3& p : test::surface_points(f, lo, hi, 60, rng)) pts.push_back(p);
  return pts;
}

class KindTableConformance : public ::testing::TestWithParam<std::tuple<size_t, EvalConfig>> {};

TEST_P(KindTableConformance, MatchesReference) {
  const auto& [index, cfg] = GetParam();
  const KindScene& s = kind_scenes().at(index);
  ir::Module m = test::compile_text(s.yaml, s.name + ".yaml", cfg.overrides());
  std::mt19937_64 rng(0x7ab1e + index);
  std::vector<V3> pts;
  std::vector<size_t> owner;  // the cell each point was drawn for
  for (size_t c = 0; c < s.cells.size(); ++c)
    for (const V3& p : cell_points(m, s.cells[c], rng)) pts.push_back(p), owner.push_back(c);
  // A fractal's estimator is ill-conditioned inside: the suite's fractal tolerance.
  Tolerance tol = kernel_tolerance(cfg.dbl);
  if (m.graph->node(m.root).props.cls == ir::DistanceClass::Estimate)
    tol = cfg.dbl ? Tolerance{1e-9, 0x1p-23} : Tolerance{2e-4, 2e-3, 5e-3, 0.5};
  ProbeCheck pc = probe_and_compare(m, cfg, pts, tol);
  // On and just inside its own example's surface a point gets the
  // example's material (the others are more than a cell away; far off the
  // surface a bounds box may answer first, with no material).
  for (size_t i = 0; i < pc.points.size(); ++i) {
    if (pc.ref_d[i] > 0.05) continue;
    const KindCell& c = s.cells[owner[i]];
    ASSERT_EQ(m.plan.materials.at(pc.ref_mat[i]).name, c.material())
        << c.kind->yaml << " at (" << pc.points[i][0] << ", " << pc.points[i][1] << ", " << pc.points[i][2] << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, KindTableConformance,
                         ::testing::Combine(::testing::Range(size_t(0), kind_scenes().size()),
                                            ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) {
                           return kind_scenes().at(std::get<0>(info.param)).name + "_" +
                                  std::get<1>(info.param).name();
                         });

// ---- dual normals ------------------------------------------------------------

// Every primitive that claims dual normals, in one scene: at its surface
// the dual normal agrees with central differences of the same kernel
// (the fractals' dual normals have DualNormalsFractals).
class KindTableDualNormals : public ::testing::TestWithParam<bool> {};

TEST_P(KindTableDualNormals, AgreeWithCentralDifferences) {
  bool dbl = GetParam();
  std::vector<const kinds::Description*> dual;
  for (const kinds::Description* d : kinds::all()) {
    if (!d->dual_normals) continue;
    ir::Module one = compile_example(*d);
    if (fits_a_cell(*d, one.graph->node(one.root).props.bounds)) dual.push_back(d);
  }
  if (dual.empty()) GTEST_SKIP() << "no described kind claims dual normals";
  KindScene s = grid_scene("dual_kinds", dual);
  ir::Module m = test::compile_text("render: {normals: dual}\n" + s.yaml, "dual_kinds.yaml",
                                    {std::string("render.precision=") + (dbl ? "double" : "float")});
  std::mt19937_64 rng(0xd0a1);
  auto f = [&](const V3& p) { return reference::distance(m, p); };
  const int width = 8;
  std::vector<V3> pts;
  std::vector<size_t> first;  // where each cell's points start
  for (const KindCell& c : s.cells) {
    first.push_back(pts.size());
    std::vector<V3> on = test::surface_points(f, sub(c.lo, {0.1, 0.1, 0.1}), add(c.hi, {0.1, 0.1, 0.1}), 120, rng);
    ASSERT_GE(on.size(), 100u) << c.kind->yaml;
    pts.insert(pts.end(), on.begin(), on.end());
  }
  first.push_back(pts.size());
  std::vector<float> out = test::run_point_kernel(normal_kernel(m, width), "normal_probe", pts, width);
  for (size_t c = 0; c < s.cells.size(); ++c) {
    // Points within the difference's reach of an edge may disagree: allow 2%.
    int off = 0, n = int(first[c + 1] - first[c]);
    for (size_t i = first[c]; i < first[c + 1]; ++i)
      off += std::acos(std::clamp(double(out[i]), -1.0, 1.0)) * 180 / std::numbers::pi > 0.5;
    EXPECT_LE(off, n / 50) << s.cells[c].kind->yaml << ": " << off << " of " << n
                           << " surface normals more than 0.5 degrees from central differences";
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, KindTableDualNormals, ::testing::Bool(),
                         [](const auto& info) { return std::string(info.param ? "double" : "float"); });

// ---- the reference against brute force -------------------------------------

// The zero crossings of f on lines along x, y and z through a grid of
// `lines` x `lines` over the box, `steps` samples a line, each bisected.
std::vector<V3> crossings(const std::function<double(const V3&)>& f, const V3& lo, const V3& hi, int lines,
                          int steps) {
  std::vector<V3> out;
  for (int axis = 0; axis < 3; ++axis) {
    int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int i = 0; i < lines; ++i)
      for (int j = 0; j < lines; ++j) {
        V3 p;
        p[u] = lo[u] + (hi[u] - lo[u]) * (i + 0.5) / lines;
        p[v] = lo[v] + (hi[v] - lo[v]) * (j + 0.5) / lines;
        auto at = [&](double t) {
          V3 q = p;
          q[axis] = lo[axis] + (hi[axis] - lo[axis]) * t;
          return q;
        };
        double prev = f(at(0));
        for (int k = 1; k <= steps; ++k) {
          double t0 = double(k - 1) / steps, t1 = double(k) / steps, d = f(at(t1));
          if ((prev < 0) != (d < 0)) {
            bool neg0 = prev < 0;
            for (int b = 0; b < 40; ++b) {
              double tm = 0.5 * (t0 + t1);
              ((f(at(tm)) < 0) == neg0 ? t0 : t1) = tm;
            }
            out.push_back(at(0.5 * (t0 + t1)));
          }
          prev = d;
        }
      }
  }
  return out;
}

class KindTableOracle : public ::testing::TestWithParam<const kinds::Description*> {};

TEST_P(KindTableOracle, ReferenceAgreesWithBruteForce) {
  const kinds::Description& d = *GetParam();
  if (ir::info(d.kind).category != ir::Category::Primitive)
    GTEST_SKIP() << d.yaml << " is not a primitive: its distance depends on its children (see its own suite)";
  // The kind's own distance on its node, in the node's frame (the module
  // around it may add transforms and a bounds box that answers far off).
  ir::Module m = compile_example(d);
  const ir::Node* node = nullptr;
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (m.graph->node(id).kind == d.kind) node = &m.graph->node(id);
  ASSERT_NE(node, nullptr) << d.yaml << ": the example lost its node";
  if (!node->props.bounds.finite()) GTEST_SKIP() << d.yaml << " is unbounded: its textbook check is in PrimitiveOracle";
  V3 lo = node->props.bounds.lo, hi = node->props.bounds.hi;
  V3 mid = mul(add(lo, hi), 0.5), half = mul(sub(hi, lo), 0.5 * 1.1);
  for (double& h : half) h = std::max(h, 0.05);
  lo = sub(mid, half), hi = add(mid, half);
  const int lines = 40;
  double spacing = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / lines;
  auto f = [&](const V3& p) { return d.distance(*node, p); };
  std::vector<V3> surface = crossings(f, lo, hi, lines, 4 * lines);
  ASSERT_GT(surface.size(), 100u) << d.yaml << ": the surface was not found in its bounds";
  bool exact = node->props.cls == ir::DistanceClass::Exact;
  std::mt19937_64 rng(std::hash<std::string_view>{}(d.yaml));
  V3 wide_lo = sub(mid, mul(half, 1.6)), wide_hi = add(mid, mul(half, 1.6));
  int over = 0, under = 0;
  double worst_over = 0, worst_under = 0;
  for (int i = 0; i < 300; ++i) {
    V3 p = test::uniform_in(rng, wide_lo, wide_hi);
    double brute = 1e300;
    for (const V3& s : surface) brute = std::min(brute, norm(sub(p, s)));
    double got = std::fabs(f(p));
    // Never more than the distance to a surface point (a bound); for an
    // exact kind no less than it minus the sampling's gaps.
    if (got > brute + 1e-6) ++over, worst_over = std::max(worst_over, got - brute);
    if (exact && got < brute - 1.5 * spacing) ++under, worst_under = std::max(worst_under, brute - got);
  }
  EXPECT_EQ(over, 0) << d.yaml << ": the reference overstates the distance by up to " << worst_over;
  EXPECT_EQ(under, 0) << d.yaml << " (exact): the reference understates the distance by up to " << worst_under;
}

INSTANTIATE_TEST_SUITE_P(Kinds, KindTableOracle, ::testing::ValuesIn(kinds::all()),
                         [](const auto& info) { return std::string(ir::info(info.param->kind).name); });

}  // namespace
}  // namespace sdfc::conformance
