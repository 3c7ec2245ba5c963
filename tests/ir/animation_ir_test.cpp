// Animated parameters in the IR: part of the hash-consing key, kept apart
// by the folding passes, bounded over every time, and taken at one time for
// the reference.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_text.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/at_time.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc {
namespace {

size_t count_kind(const ir::Module& m, ir::Kind k) {
  size_t n = 0;
  for (ir::NodeId id : m.graph->postorder(m.root)) n += m.graph->node(id).kind == k;
  return n;
}

TEST(AnimatedIr, SameExpressionSharesANodeAndAnotherDoesNot) {
  ir::Module m = passes::run_pipeline(test::lower_text(
      "scene:\n  union:\n"
      "    - {sphere: {radius: \"0.5 + 0.1*sin(time)\"}, translate: [1, 0, 0]}\n"
      "    - {sphere: {radius: \"0.5 + 0.1*sin(time)\"}, translate: [-1, 0, 0]}\n"
      "    - {sphere: {radius: \"0.5 + 0.1*cos(time)\"}, translate: [0, 1, 0]}\n"
      "    - {sphere: {radius: 0.5}, translate: [0, -1, 0]}\n"));
  EXPECT_EQ(count_kind(m, ir::Kind::Sphere), 3u);  // sin (shared), cos, static
  EXPECT_TRUE(m.graph->animated(m.root));
  EXPECT_NE(ir::print(m, {}).find("radius=\"(0.5 + (0.1 * sin(time)))\""), std::string::npos) << ir::print(m, {});
}

TEST(AnimatedIr, AnimatedTransformsDoNotMerge) {
  // Two static translations merge; an animated one stays its own node.
  ir::Module still = passes::run_pipeline(test::lower_text(
      "scene: {union: [{sphere: {}, translate: [1, 0, 0]}], translate: [0, 1, 0]}\n"));
  ir::Module moving = passes::run_pipeline(test::lower_text(
      "scene: {union: [{sphere: {}, translate: [\"sin(time)\", 0, 0]}], translate: [0, 1, 0]}\n"));
  EXPECT_EQ(count_kind(still, ir::Kind::Translate), 1u);
  EXPECT_EQ(count_kind(moving, ir::Kind::Translate), 2u);
  // The field at time t is the static scene with the values at t.
  ir::Module then = reference::at_time(moving, 2.0);
  ir::Module fixed = passes::run_pipeline(test::lower_text(
      "scene: {sphere: {}, translate: [" + std::to_string(std::sin(2.0)) + ", 1, 0]}\n"));
  for (double x : {-2.0, 0.0, 0.7, 1.5})
    EXPECT_NEAR(reference::distance(then, {x, 0.3, 0.2}), reference::distance(fixed, {x, 0.3, 0.2}), 1e-6);
}

TEST(AnimatedIr, BoundsHoldAtEveryTime) {
  ir::Module m = passes::run_pipeline(test::lower_text(
      "scene: {box: {size: [0.4, 0.4, \"0.4 + 0.3*sin(time)\"]}, rotate: {axis: [1, 0, 0], degrees: \"50*time\"}, "
      "translate: [\"0.5*cos(time)\", 0, 0]}\n"));
  const ir::Box3& b = m.graph->node(m.root).props.bounds;
  ASSERT_TRUE(b.finite());
  // Sample the surface's extent at many times: every corner of the box at
  // time t lies inside the inferred bounds.
  for (double t = 0; t < 20; t += 0.37) {
    double hz = 0.5 * (0.4 + 0.3 * std::sin(t)), a = 50 * t * M_PI / 180, tx = 0.5 * std::cos(t);
    for (int c = 0; c < 8; ++c) {
      double p[3] = {c & 1 ? 0.2 : -0.2, c & 2 ? 0.2 : -0.2, c & 4 ? hz : -hz};
      double w[3] = {p[0] + tx, std::cos(a) * p[1] - std::sin(a) * p[2], std::sin(a) * p[1] + std::cos(a) * p[2]};
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(w[i], b.lo[i] - 1e-9) << "t " << t;
        EXPECT_LE(w[i], b.hi[i] + 1e-9) << "t " << t;
      }
    }
  }
}

}  // namespace
}  // namespace sdfc
