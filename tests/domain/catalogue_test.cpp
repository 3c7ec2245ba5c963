// The primitive catalogue against brute force: for every primitive with an
// exact formula, |d| equals the distance to a dense sampling of its zero set
// (within the sampling's resolution) at 1000 points; for the bounds, |d|
// never exceeds it.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "surface_sampling.hpp"

namespace sdfc {
namespace {

struct Case {
  std::string name;
  std::string scene;
};

// Every described kind's example, and the capsule's segment spelling.
std::vector<Case> cases() {
  std::vector<Case> v;
  for (const kinds::Description* d : kinds::all())
    if (d->kind != ir::Kind::Plane && ir::info(d->kind).category == ir::Category::Primitive)  // no surface to sample densely in a box
      v.push_back({std::string(d->yaml), std::string(d->example)});
  v.push_back({"segment", "{segment: {a: [-0.4, 0.1, -0.3], b: [0.3, -0.2, 0.4], radius: 0.15}}"});
  return v;
}

class Catalogue : public ::testing::TestWithParam<Case> {};

TEST_P(Catalogue, DistanceMatchesBruteForce) {
  const Case& c = GetParam();
  ir::Module m = passes::run_pipeline(test::lower_text(std::string("scene: ") + c.scene + "\n"));
  // The primitive's own field: a costly one is wrapped in a bounding box at
  // the root, which stands in (as a lower bound) far away.
  ir::NodeId geometry = m.root;
  if (m.graph->node(geometry).kind == ir::Kind::Bounded) geometry = m.graph->node(geometry).children[0];
  const ir::Box3& b = m.graph->node(geometry).props.bounds;
  ASSERT_TRUE(b.finite()) << c.name;
  // Exact kinds must match the brute force both ways; bounds only from below.
  const bool exact = m.graph->node(geometry).props.cls == ir::DistanceClass::Exact;
  test::Field f = [&](const test::P3& p) { return reference::evaluate(*m.graph, geometry, p).distance; };
  test::P3 lo{b.lo[0] - 0.05, b.lo[1] - 0.05, b.lo[2] - 0.05}, hi{b.hi[0] + 0.05, b.hi[1] + 0.05, b.hi[2] + 0.05};
  test::Sampling s = test::sample_surface(f, lo, hi, 110);
  ASSERT_GT(s.points.size(), 2000u) << c.name;
  // Every sample lies inside the inferred bounds (the bounds are right).
  for (const auto& p : s.points)
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(p[i] >= b.lo[i] - 1e-6 && p[i] <= b.hi[i] + 1e-6) << c.name;
  double slack = s.spacing * std::sqrt(3.0) + 1e-6;
  int inside = 0;
  for (const test::P3& p : test::points_in({lo[0] - 0.5, lo[1] - 0.5, lo[2] - 0.5}, {hi[0] + 0.5, hi[1] + 0.5, hi[2] + 0.5}, 1000)) {
    double d = f(p), brute = test::nearest(s.points, p);
    inside += d < 0;
    // Never more than the true distance (samples lie on the surface).
    ASSERT_LE(std::fabs(d), brute + 1e-6) << c.name << " at " << p[0] << "," << p[1] << "," << p[2];
    if (exact) {
      ASSERT_GE(std::fabs(d), brute - slack) << c.name << " at " << p[0] << "," << p[1] << "," << p[2];
    }
  }
  EXPECT_GT(inside, 0) << c.name << ": no test point inside";
}

INSTANTIATE_TEST_SUITE_P(Primitives, Catalogue, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(CatalogueSchema, ReportsImpossibleShapes) {
  auto first = [](const std::string& scene) {
    auto e = test::errors_of("scene: " + scene + "\n");
    return e.empty() ? std::string() : e[0].message;
  };
  EXPECT_NE(first("{round_cone: {height: 0.1, bottom_radius: 0.5, top_radius: 0.1}}").find("must exceed"), std::string::npos);
  EXPECT_NE(first("{quad: {a: [0,0,0], b: [1,0,0], c: [1,1,0.5], d: [0,1,0]}}").find("must be flat"), std::string::npos);
  EXPECT_NE(first("{quad: {a: [0,0,0], b: [1,1,0], c: [1,0,0], d: [0,1,0]}}").find("convex"), std::string::npos);
  EXPECT_NE(first("{triangle: {a: [0,0,0], b: [1,0,0], c: [2,0,0]}}").find("one line"), std::string::npos);
  EXPECT_NE(first("{box_frame: {size: [1,1,1], edge: 0.6}}").find("half the smallest"), std::string::npos);
  EXPECT_NE(first("{cone: {radius: 1, hieght: 2}}").find("hieght"), std::string::npos);
}

}  // namespace
}  // namespace sdfc
