// Each pass on its own: node counts before and after, and what it keeps.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_text.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc {
namespace {

size_t count(const ir::Module& m) { return ir::count_nodes(m); }

size_t count_kind(const ir::Module& m, ir::Kind k) {
  size_t n = 0;
  for (ir::NodeId id : m.graph->postorder(m.root)) n += m.graph->node(id).kind == k;
  return n;
}

// The passes must not change the distance anywhere.
void expect_same_field(const ir::Module& a, const ir::Module& b) {
  for (double x = -2; x <= 2; x += 0.37)
    for (double y = -2; y <= 2; y += 0.41)
      for (double z = -2; z <= 2; z += 0.43) {
        reference::Vec3 p{x, y, z};
        auto sa = reference::evaluate(*a.graph, a.root, p), sb = reference::evaluate(*b.graph, b.root, p);
        ASSERT_NEAR(sa.distance, sb.distance, 1e-9) << x << " " << y << " " << z;
      }
}

TEST(FoldConstants, MergesNestedTranslatesAndCollapsesOneChildUnions) {
  ir::Module m = test::lower_text(
      "scene:\n"
      "  union:\n"
      "    - union:\n"
      "        - {sphere: {radius: 1}, translate: [1, 0, 0]}\n"
      "      translate: [0, 2, 0]\n");
  EXPECT_EQ(count(m), 5u);  // sphere, translate, union, translate, union
  ir::Module f = passes::fold_constants(m);
  EXPECT_EQ(count(f), 2u);  // sphere, one translate
  EXPECT_EQ(ir::print(f, {.props = false, .plan = false}), "%0 = sphere radius=1\n%1 = translate x=1 y=2 z=0 %0\nroot = %1\n");
  expect_same_field(m, f);
}

TEST(FoldConstants, IdentityTransformsVanish) {
  ir::Module m = test::lower_text(
      "scene: {sphere: {radius: 1}, translate: [0, 0, 0], rotate: {axis: [0, 0, 1], degrees: 0}, scale: 1}\n");
  EXPECT_EQ(count(m), 4u);
  EXPECT_EQ(count(passes::fold_constants(m)), 1u);
}

TEST(FoldConstants, MergesRotationsAndScales) {
  ir::Module m = test::lower_text(
      "scene:\n  union:\n    - {box: {size: [1, 2, 3]}, rotate: [0, 0, 30], scale: 2}\n"
      "  rotate: [0, 0, 60]\n  scale: 0.5\n");
  ir::Module f = passes::run_pipeline(m);
  EXPECT_EQ(count_kind(f, ir::Kind::Rotate), 1u);
  EXPECT_EQ(count_kind(f, ir::Kind::Scale), 0u);  // 2 * 0.5 = 1 folds away
  expect_same_field(m, f);
}

TEST(FoldConstants, InnerMaterialWins) {
  ir::Module m = test::lower_text(
      "materials: {a: {}, b: {}}\nscene:\n  union:\n    - {sphere: {radius: 1}, material: a}\n  material: b\n");
  ir::Module f = passes::run_pipeline(m);
  EXPECT_EQ(count_kind(f, ir::Kind::Material), 1u);
  EXPECT_EQ(f.plan.materials.size(), 2u);  // default + a; b is dead
  EXPECT_EQ(f.plan.materials[1].name, "a");
}

TEST(Canonicalise, FlattensNestedUnionsAndSharesReorderedOnes) {
  ir::Module m = test::lower_text(
      "scene:\n  intersection:\n"
      "    - union: [{sphere: {radius: 1}}, {union: [{box: {size: [1, 1, 1]}}, {torus: {}}]}]\n"
      "    - union: [{union: [{torus: {}}, {box: {size: [1, 1, 1]}}]}, {sphere: {radius: 1}}]\n");
  ir::Module c = passes::cse(passes::canonicalise(passes::fold_constants(m)));
  EXPECT_EQ(count_kind(c, ir::Kind::Union), 1u);  // both unions became the same flat one
  EXPECT_EQ(count(c), 4u);                        // sphere, box, torus, union (the 1-child intersection folded)
  expect_same_field(m, c);
}

TEST(Canonicalise, PushesTranslatesOutwardSoTheyMerge) {
  // scale(2, translate(t)) -> translate(2t, scale(2)): the outer translate then merges.
  ir::Module m = test::lower_text(
      "scene:\n  union:\n    - {sphere: {radius: 1}, translate: [1, 0, 0]}\n  scale: 2\n  translate: [0, 0, 1]\n");
  ir::Module c = passes::run_pipeline(m);
  EXPECT_EQ(count_kind(c, ir::Kind::Translate), 1u);
  EXPECT_EQ(ir::print(c, {.props = false, .plan = false}),
            "%0 = sphere radius=1\n%1 = scale s=2 %0\n%2 = translate x=2 y=0 z=1 %1\nroot = %2\n");
  expect_same_field(m, c);
}

TEST(EliminateDead, UnusedMaterialsAndDarkLights) {
  ir::Module m = test::lower_text(
      "materials: {unused: {}, used: {color: [1, 0, 0]}}\n"
      "lights:\n  - directional: {direction: [0, 0, -1], intensity: 0}\n  - point: {position: [0, 0, 3]}\n"
      "scene: {sphere: {radius: 1}, material: used}\n");
  EXPECT_EQ(m.plan.materials.size(), 3u);
  ir::Module d = passes::eliminate_dead(m);
  ASSERT_EQ(d.plan.materials.size(), 2u);
  EXPECT_EQ(d.plan.materials[1].name, "used");
  EXPECT_EQ(d.graph->node(d.root).params[0], 1.0);  // renumbered from 2 to 1
  ASSERT_EQ(d.plan.lights.size(), 2u);               // the point light and the ambient fill
  EXPECT_EQ(d.plan.lights[0].kind, ir::LightKind::Point);
}

TEST(InferProperties, BoundsAndClasses) {
  ir::Module m = passes::run_pipeline(test::lower_text(
      "scene:\n  union:\n    - {sphere: {radius: 1}, translate: [3, 0, 0]}\n    - mandelbulb: {power: 8}\n"));
  const ir::Props& p = m.graph->node(m.root).props;
  EXPECT_EQ(p.cls, ir::DistanceClass::Estimate);  // the worst child's class
  EXPECT_NEAR(p.bounds.hi[0], 4.0, 1e-12);
  EXPECT_NEAR(p.bounds.lo[0], -std::pow(2.0, 1.0 / 7.0), 1e-12);
  ir::Module plane = passes::run_pipeline(test::lower_text("scene: {plane: {normal: [0, 0, 1]}}\n"));
  EXPECT_FALSE(plane.graph->node(plane.root).props.bounds.finite());
}

TEST(InsertBoundingVolumes, WrapsExpensiveUnionChildrenOnly) {
  ir::Module m = passes::run_pipeline(test::lower_text(
      "scene:\n  union:\n    - mandelbulb: {power: 8}\n    - {sphere: {radius: 0.5}, translate: [3, 0, 0]}\n"
      "    - plane: {normal: [0, 0, 1], offset: -2}\n"));
  // The fractal is wrapped; the cheap sphere is not, nor the unbounded root.
  EXPECT_EQ(count_kind(m, ir::Kind::Bounded), 1u);
  const ir::Node& u = m.graph->node(m.root);
  ASSERT_EQ(u.kind, ir::Kind::Union);
  size_t wrapped = 0;
  for (ir::NodeId c : u.children) {
    const ir::Node& k = m.graph->node(c);
    if (k.kind != ir::Kind::Bounded) continue;
    ++wrapped;
    EXPECT_EQ(m.graph->node(k.children[0]).kind, ir::Kind::Mandelbulb);
  }
  EXPECT_EQ(wrapped, 1u);
}

// Built from exact primitives, so "lower bound" can be checked against the
// true distance: a smooth union of spheres is costly enough to be wrapped.
TEST(InsertBoundingVolumes, KeepsTheFieldALowerBoundAndExactNearby) {
  std::string blob = "    - smooth_union:\n        radius: 0.2\n        children:\n";
  for (int i = 0; i < 12; ++i)
    blob += "          - {sphere: {radius: 0.3}, translate: [" + std::to_string(0.25 * (i % 4)) + ", " +
            std::to_string(0.25 * (i / 4)) + ", 0]}\n";
  std::string scene = "scene:\n  union:\n" + blob + "    - {box: {size: [0.5, 0.5, 0.5]}, translate: [3, 0, 0]}\n";
  ir::Module m = test::lower_text(scene);
  for (const auto& pass : passes::pipeline())
    if (pass.name != "insert_bounding_volumes") m = pass.run(std::move(m));
  ir::Module bounded = passes::insert_bounding_volumes(m);
  EXPECT_EQ(count_kind(bounded, ir::Kind::Bounded), 2u);  // the blob and the whole scene
  size_t skipped = 0;
  for (double x = -3; x <= 5; x += 0.31)
    for (double y = -3; y <= 3; y += 0.37)
      for (double z = -3; z <= 3; z += 0.41) {
        reference::Vec3 p{x, y, z};
        double exact = reference::distance(m, p), fast = reference::distance(bounded, p);
        ASSERT_LE(fast, exact + 1e-12) << x << " " << y << " " << z;  // still a lower bound
        if (std::fabs(exact) < 0.2) {
          ASSERT_DOUBLE_EQ(fast, exact) << "changed near a surface";
        }
        skipped += fast < exact;
      }
  EXPECT_GT(skipped, 100u);  // the box really stands in somewhere
}

TEST(Verify, RejectsBrokenIr) {
  ir::Module m = test::lower_text("scene: {sphere: {radius: 1}}\n");
  EXPECT_NO_THROW(passes::verify(m));
  ir::Module broken = m;
  broken.root = ir::kNoNode;
  EXPECT_THROW(passes::verify(broken), std::logic_error);
}

TEST(Pipeline, EveryPassIsObserved) {
  std::vector<std::string> seen;
  passes::run_pipeline(test::lower_text("scene: {sphere: {radius: 1}}\n"),
                       [&](std::string_view name, const ir::Module&) { seen.emplace_back(name); });
  ASSERT_EQ(seen.size(), passes::pipeline().size());
  EXPECT_EQ(seen.front(), "verify");
  EXPECT_EQ(seen.back(), "gather_object_sets");
}

}  // namespace
}  // namespace sdfc
