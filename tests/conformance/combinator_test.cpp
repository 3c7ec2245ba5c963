// Combinators and smooth blends, and material tracking through them:
//  - every OpenCL evaluator against the CPU reference (distance, the
//    material variant's distance, and the material id wherever the winning
//    child is unambiguous) — CombinatorConformance;
//  - the reference against the combination, computed here, of its parts'
//    distances (min / max / max(a, -b) / textbook smooth blends), and its
//    material against the winning part's — CombinatorOracle.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "conformance.hpp"

namespace sdfc::conformance {
namespace {

using test::add;
using test::mul;

const char* kMaterials =
    "materials:\n"
    "  m1: {color: [0.9, 0.2, 0.1]}\n"
    "  m2: {color: [0.1, 0.3, 0.9]}\n"
    "  m3: {color: [0.2, 0.8, 0.2]}\n";

// A leaf of a combinator scene as a standalone world-space scene, and the
// name of the material it carries. (Names, not ids: eliminate_dead drops
// unused materials and renumbers the rest.)
struct Part {
  std::string yaml;  // a geometry node as a YAML flow map
  std::string material;
};

enum class Op { Union, Intersection, Difference, SmoothUnion, SmoothIntersection, SmoothDifference };

struct CombScene {
  std::string name;
  Op op;
  double k = 0;             // blend radius of the smooth ops
  std::vector<Part> parts;  // the children (or, for a nested scene, the leaves)
  std::string custom;       // scene body when the scene is not just op(parts)

  std::string yaml() const {
    std::string s = std::string(kMaterials) + "scene:\n";
    if (!custom.empty()) return s + custom;
    static const char* names[] = {"union", "intersection", "difference", "smooth_union", "smooth_intersection",
                                  "smooth_difference"};
    const char* n = names[int(op)];
    if (k > 0) {
      s += fmt::format("  {}:\n    radius: {}\n    children:\n", n, k);
      for (const auto& p : parts) s += "      - " + p.yaml + "\n";
    } else {
      s += fmt::format("  {}:\n", n);
      for (const auto& p : parts) s += "    - " + p.yaml + "\n";
    }
    return s;
  }
};

void PrintTo(const CombScene& s, std::ostream* os) { *os << s.name; }

std::vector<CombScene> comb_scenes() {
  std::vector<CombScene> v;
  v.push_back({"union", Op::Union, 0,
               {{"{sphere: {radius: 0.6}, translate: [-0.5, 0, 0], material: m1}", "m1"},
                {"{box: {size: [0.8, 0.8, 0.8]}, rotate: {axis: [0, 0, 1], degrees: 30}, translate: [0.5, 0.1, 0], "
                 "material: m2}",
                 "m2"},
                {"{torus: {major_radius: 0.5, minor_radius: 0.15}, translate: [0, 0, 0.6]}", "default"}},
               ""});
  v.push_back({"intersection", Op::Intersection, 0,
               {{"{sphere: {radius: 0.9}, material: m1}", "m1"},
                {"{box: {size: [1.2, 1.2, 1.2]}, rotate: [10, 20, 30], material: m2}", "m2"},
                {"{cylinder: {radius: 0.55, height: 2}, rotate: {axis: [1, 0, 0], degrees: 90}, material: m3}", "m3"}},
               ""});
  v.push_back({"difference", Op::Difference, 0,
               {{"{box: {size: [1.4, 1.4, 1.4], radius: 0.1}, material: m1}", "m1"},
                {"{sphere: {radius: 0.85}, material: m2}", "m2"},
                {"{cylinder: {radius: 0.3, height: 3}, rotate: {axis: [0, 1, 0], degrees: 90}, material: m3}", "m3"}},
               ""});
  v.push_back({"smooth_union", Op::SmoothUnion, 0.3,
               {{"{sphere: {radius: 0.5}, translate: [-0.35, 0, 0], material: m1}", "m1"},
                {"{capsule: {a: [0.1, -0.3, -0.4], b: [0.6, 0.2, 0.5], radius: 0.25}, material: m2}", "m2"}},
               ""});
  v.push_back({"smooth_intersection", Op::SmoothIntersection, 0.2,
               {{"{box: {size: [1.2, 1.2, 1.2]}, material: m1}", "m1"}, {"{sphere: {radius: 0.78}, material: m2}", "m2"}},
               ""});
  v.push_back({"smooth_difference", Op::SmoothDifference, 0.15,
               {{"{box: {size: [1.2, 1.2, 1.2], radius: 0.05}, material: m1}", "m1"},
                {"{cylinder: {radius: 0.4, height: 2}, material: m2}", "m2"}},
               ""});
  // Nested unions with materials at two levels: the material nearest the
  // geometry wins (the sphere keeps m1 inside the m2 group, the box takes
  // m2), a plain nested union is flattened, the capsule has none.
  v.push_back({"nested_materials", Op::Union, 0,
               {{"{sphere: {radius: 0.5}, translate: [-0.6, 0, 0], material: m1}", "m1"},
                {"{box: {size: [0.6, 0.6, 0.6]}, translate: [0.1, 0, 0], material: m2}", "m2"},
                {"{torus: {major_radius: 0.4, minor_radius: 0.12}, translate: [0.6, 0.2, 0.3], material: m3}", "m3"},
                {"{capsule: {a: [0.4, -0.5, -0.3], b: [0.9, -0.4, 0.4], radius: 0.15}}", "default"}},
               "  union:\n"
               "    - union:\n"
               "        - {sphere: {radius: 0.5}, material: m1}\n"
               "        - {box: {size: [0.6, 0.6, 0.6]}, translate: [0.7, 0, 0]}\n"
               "      material: m2\n"
               "      translate: [-0.6, 0, 0]\n"
               "    - union:\n"
               "        - {torus: {major_radius: 0.4, minor_radius: 0.12}, translate: [0.6, 0.2, 0.3], material: m3}\n"
               "        - {capsule: {a: [0.4, -0.5, -0.3], b: [0.9, -0.4, 0.4], radius: 0.15}}\n"});
  return v;
}

// Textbook smooth minimum (Quilez's polynomial smin in its mix form,
// algebraically equal to the max(k - |a - b|, 0) form the stdlib uses).
double smin(double a, double b, double k) {
  double h = std::clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return b * (1 - h) + a * h - k * h * (1 - h);
}
double smax(double a, double b, double k) { return -smin(-a, -b, k); }

// Parts' distances at p, combined as the scene's op does.
double fold(const CombScene& sc, const std::vector<double>& d) {
  double acc = d[0];
  for (size_t i = 1; i < d.size(); ++i) switch (sc.op) {
      case Op::Union: acc = std::min(acc, d[i]); break;
      case Op::Intersection: acc = std::max(acc, d[i]); break;
      case Op::Difference: acc = std::max(acc, -d[i]); break;
      case Op::SmoothUnion: acc = smin(acc, d[i], sc.k); break;
      case Op::SmoothIntersection: acc = smax(acc, d[i], sc.k); break;
      case Op::SmoothDifference: acc = smax(acc, -d[i], sc.k); break;
    }
  return acc;
}

// The part whose material the result carries, or -1 when two candidates are
// within 1e-3 of each other (then either answer is right).
int winner(const CombScene& sc, const std::vector<double>& d) {
  if (sc.op == Op::Difference || sc.op == Op::SmoothDifference) return 0;  // the cut keeps the first child's
  bool lowest = sc.op == Op::Union || sc.op == Op::SmoothUnion;
  std::vector<size_t> order(d.size());
  for (size_t i = 0; i < d.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return lowest ? d[a] < d[b] : d[a] > d[b]; });
  if (std::fabs(d[order[0]] - d[order[1]]) <= 1e-3) return -1;
  return int(order[0]);
}

std::string mat_name(const ir::Module& m, int id) {
  return id >= 0 && size_t(id) < m.plan.materials.size() ? m.plan.materials[id].name : "#" + std::to_string(id);
}

struct Fixture {
  ir::Module scene;
  std::vector<ir::Module> parts;
  std::vector<V3> points;  // float-rounded, so the kernel sees exactly these
  std::vector<std::vector<double>> part_d;
};

Fixture make(const CombScene& sc, const std::vector<std::string>& overrides) {
  Fixture f;
  f.scene = test::compile_text(sc.yaml(), sc.name + ".yaml", overrides);
  for (const auto& p : sc.parts) f.parts.push_back(test::compile_text(std::string(kMaterials) + "scene: " + p.yaml));
  std::mt19937_64 rng(std::hash<std::string>{}(sc.name) ^ 0xc0b);
  V3 lo{-1.6, -1.6, -1.6}, hi{1.6, 1.6, 1.6};
  for (int i = 0; i < 1200; ++i) f.points.push_back(test::uniform_in(rng, lo, hi));
  auto d = [&](const V3& p) { return reference::distance(f.scene, p); };
  for (const auto& p : test::surface_points(d, lo, hi, 300, rng)) f.points.push_back(p);
  std::uniform_real_distribution<double> far(4.0, 40.0);
  for (int i = 0; i < 100; ++i) f.points.push_back(mul(test::random_unit(rng), far(rng)));
  for (auto& p : f.points) {
    p = test::to_float_point(p);
    std::vector<double> pd;
    for (const auto& pm : f.parts) pd.push_back(reference::distance(pm, p));
    f.part_d.push_back(pd);
  }
  return f;
}

// ---- every evaluator against the reference ---------------------------------

class CombinatorConformance : public ::testing::TestWithParam<std::tuple<CombScene, EvalConfig>> {};

TEST_P(CombinatorConformance, MatchesReference) {
  const auto& [sc, cfg] = GetParam();
  Fixture f = make(sc, cfg.overrides());
  ASSERT_GE(f.points.size(), 1500u);
  std::vector<char> unambiguous;
  int n_checked = 0;
  for (const auto& pd : f.part_d) {
    unambiguous.push_back(winner(sc, pd) >= 0);
    n_checked += unambiguous.back();
  }
  EXPECT_GT(n_checked, 1000) << "too few points with a clear winner";
  probe_and_compare(f.scene, cfg, f.points, kernel_tolerance(cfg.dbl), unambiguous);
}

INSTANTIATE_TEST_SUITE_P(Combinators, CombinatorConformance,
                         ::testing::Combine(::testing::ValuesIn(comb_scenes()), ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) { return std::get<0>(info.param).name + "_" + std::get<1>(info.param).name(); });

// ---- the oracle ----------------------------------------------------------------

class CombinatorOracle : public ::testing::TestWithParam<CombScene> {};

// The reference of the whole scene (after flattening, sorting and transform
// pushing by the passes) equals the fold of its parts' distances, and its
// material is the winning part's. Parts and whole are both double; 1e-12
// absorbs only rounding.
TEST_P(CombinatorOracle, ReferenceIsTheFoldOfItsParts) {
  const CombScene& sc = GetParam();
  Fixture f = make(sc, {});
  for (size_t i = 0; i < sc.parts.size(); ++i)
    EXPECT_EQ(mat_name(f.parts[i], reference::evaluate(*f.parts[i].graph, f.parts[i].root, {9, 9, 9}).material),
              sc.parts[i].material)
        << "part " << i << " carries an unexpected material";
  int bad_d = 0, bad_mat = 0;
  std::string msgs;
  for (size_t i = 0; i < f.points.size(); ++i) {
    reference::Sample s = reference::evaluate(*f.scene.graph, f.scene.root, f.points[i]);
    double want = fold(sc, f.part_d[i]);
    if (!(std::fabs(s.distance - want) <= 1e-12 * (1 + std::fabs(want))) && bad_d++ < 5)
      msgs += fmt::format("  distance at ({}, {}, {}): reference {}, fold of parts {}\n", f.points[i][0],
                          f.points[i][1], f.points[i][2], s.distance, want);
    int w = winner(sc, f.part_d[i]);
    if (w >= 0 && mat_name(f.scene, s.material) != sc.parts[w].material && bad_mat++ < 5)
      msgs += fmt::format("  material at ({}, {}, {}): reference {}, winning part {} has {}\n", f.points[i][0],
                          f.points[i][1], f.points[i][2], mat_name(f.scene, s.material), w, sc.parts[w].material);
  }
  EXPECT_EQ(bad_d, 0) << msgs;
  EXPECT_EQ(bad_mat, 0) << msgs;
  expect_inside_bounds(f.scene, f.points);
}

INSTANTIATE_TEST_SUITE_P(Combinators, CombinatorOracle, ::testing::ValuesIn(comb_scenes()),
                         [](const auto& info) { return info.param.name; });

// ---- smooth blends are neither idempotent nor associative -------------------
//
// smin(a, a) = a - k/4, not a, and for three or more children
// smin(smin(a, b), c) depends on the order, so canonicalise must keep smooth
// children as written (it once sorted and deduplicated them like min/max).
TEST(SmoothBlendSemantics, DuplicateChildrenStillBlend) {
  ir::Module m = test::compile_text(
      "scene: {smooth_union: {radius: 0.4, children: [{sphere: {radius: 1}}, {sphere: {radius: 1}}]}}\n");
  // smin(d, d, 0.4) = d - 0.1 for the two identical spheres.
  EXPECT_NEAR(reference::distance(m, {0, 0, 2}), 1.0 - 0.1, 1e-12);
}

TEST(SmoothBlendSemantics, ThreeChildrenFoldInSourceOrder) {
  CombScene sc{"three",
               Op::SmoothUnion,
               0.5,
               {{"{sphere: {radius: 0.5}, translate: [-0.3, 0, 0]}", "default"},
                {"{sphere: {radius: 0.5}, translate: [0.3, 0, 0]}", "default"},
                {"{box: {size: [0.4, 0.4, 0.4]}, translate: [0, 0.45, 0]}", "default"}},
               ""};
  Fixture f = make(sc, {});
  int bad = 0;
  for (size_t i = 0; i < f.points.size(); ++i)
    bad += std::fabs(reference::distance(f.scene, f.points[i]) - fold(sc, f.part_d[i])) > 1e-9;
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace sdfc::conformance
