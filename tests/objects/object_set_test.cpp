// Object sets (sdfc/ir/object_set.hpp): which unions the gather_object_sets
// pass turns into data, that the reference evaluates a set as the union it
// replaces, and that the kernel's hierarchy walk agrees with both at every
// SIMD width, on PoCL. The images are object_set_render_test.cpp's.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/ir/object_set.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/scene_caps.hpp"
#include "object_set_scenes.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc {
namespace {

using test::Case;
using test::cases;
using test::kHead;
using test::scene;
using test::unrolled;
using test::V3;
namespace os = ir::object_set;
constexpr size_t kThreshold = os::kLargeGroupSetMinPrims;  // this many scattered shapes are a set by either rule

size_t count(const ir::Module& m, ir::Kind k) {
  size_t c = 0;
  for (ir::NodeId id : m.graph->postorder(m.root)) c += m.graph->node(id).kind == k;
  return c;
}

std::vector<V3> points(size_t n, double spread, unsigned seed = 3) {
  std::mt19937_64 rng(seed);
  std::vector<V3> p;
  for (size_t i = 0; i < n; ++i) p.push_back(test::to_float_point(test::uniform_in(rng, {-spread, -spread, -1}, {spread, spread, 3})));
  return p;
}

TEST(ObjectSetPass, SmallGroupsGatherFromADozenPrimitivesLargeOnesOnlyInNumbers) {
  auto sets = [](size_t n, size_t group) { return count(test::compile_text(scene(n, group)), ir::Kind::ObjectSet); };
  EXPECT_EQ(sets(os::kSetMinChildren * 3, 3), 1u);         // 4 groups of three: 12 primitives
  EXPECT_EQ(sets((os::kSetMinChildren - 1) * 4, 4), 0u);   // 3 groups of four: too few children
  EXPECT_EQ(sets(os::kSetMinChildren * 2, 2), 0u);         // 4 pairs: 8 primitives
  EXPECT_EQ(sets(8 * 8, 8), 0u);                           // 8 groups of eight: large groups, too few
  EXPECT_EQ(sets((os::kLargeGroupSetMinChildren - 1) * 8, 8), 0u);  // 15 of them
  EXPECT_EQ(sets(os::kLargeGroupSetMinChildren * 5, 5), 1u);        // 16 groups of five: 80 primitives
  EXPECT_EQ(sets(os::kLargeGroupSetMinChildren * 3, 3), 1u);        // 16 groups of three
}

TEST(ObjectSetPass, GathersAtTheThresholdAndNotBelow) {
  const size_t threshold = os::kSetMinPrims;
  ir::Module below = test::compile_text(scene(threshold - 1));
  EXPECT_EQ(count(below, ir::Kind::ObjectSet), 0u);
  EXPECT_EQ(count(below, ir::Kind::Translate), threshold - 1);  // one per object (equal shapes share a node)
  ir::Module at = test::compile_text(scene(threshold));
  EXPECT_EQ(count(at, ir::Kind::ObjectSet), 1u);
  EXPECT_EQ(count(at, ir::Kind::Translate) + count(at, ir::Kind::Sphere) + count(at, ir::Kind::Box), 0u);
  EXPECT_EQ(ir::object_set::View{at.graph->node(at.root).kind == ir::Kind::ObjectSet
                                     ? at.graph->node(at.root).params
                                     : at.graph->node(at.graph->node(at.root).children[0]).params}
                .items(),
            threshold);
}

TEST(ObjectSetPass, LeavesWhatItCannotHoldAsCode) {
  // a floor beside the set; rotated boxes, animated spheres and double precision stay code
  std::string floor = "    - plane: {normal: [0, 0, 1], offset: -1}\n";
  ir::Module m = test::compile_text(scene(kThreshold, 1, floor));
  EXPECT_EQ(count(m, ir::Kind::ObjectSet), 1u);
  EXPECT_EQ(count(m, ir::Kind::Plane), 1u);
  std::string rotated = kHead;
  for (size_t i = 0; i < kThreshold; ++i)
    rotated += fmt::format("    - box: {{size: [0.2, 0.3, 0.4]}}\n      rotate: [0, 0, {}]\n      translate: [{}, 0, 0]\n", 10 + i, i);
  EXPECT_EQ(count(test::compile_text(rotated), ir::Kind::ObjectSet), 0u);
  std::string animated = kHead;
  for (size_t i = 0; i < kThreshold; ++i)
    animated += fmt::format("    - sphere: {{radius: 0.2}}\n      translate: [{}, 0, \"sin(time)\"]\n", i);
  EXPECT_EQ(count(test::compile_text(animated), ir::Kind::ObjectSet), 0u);
  EXPECT_EQ(count(test::compile_text(scene(kThreshold), "test.yaml", {"render.precision=double"}), ir::Kind::ObjectSet), 0u);
}

TEST(ObjectSetPass, CostStaysUnderTheCapButCountsPiledUpObjects) {
  ir::Module spread = test::compile_text(scene(2000));
  ir::Module piled = test::compile_text(scene(2000, 1, "", 0.01));
  EXPECT_LT(estimated_cost_per_sample(spread), estimated_cost_per_sample(unrolled(scene(2000))) / 10);
  EXPECT_GT(estimated_cost_per_sample(piled), 10 * estimated_cost_per_sample(spread));
}

TEST(ObjectSetReference, EvaluatesTheUnionItReplaces) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    ir::Module set = test::compile_text(c.yaml), code = unrolled(c.yaml);
    ASSERT_EQ(count(set, ir::Kind::ObjectSet), 1u);
    for (const V3& p : points(400, c.spread)) {
      reference::Sample a = reference::evaluate(*set.graph, set.root, p), b = reference::evaluate(*code.graph, code.root, p);
      ASSERT_NEAR(a.distance, b.distance, 1e-12 * (1 + std::fabs(b.distance)));
      EXPECT_EQ(a.material, b.material);
    }
  }
}

TEST(ObjectSetConformance, KernelWalkAgreesWithReferenceAndUnrolledKernel) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    ir::Module set = test::compile_text(c.yaml), code = unrolled(c.yaml);
    std::vector<V3> pts = points(512, c.spread);
    for (int width : {1, 8, 16, 64}) {
      SCOPED_TRACE(width);
      test::Probe probe(set, width), plain(code, width);
      ASSERT_FALSE(probe.emitted().scene_data.empty());
      test::ProbeResult got = probe.run(pts), want = plain.run(pts);
      for (size_t i = 0; i < pts.size(); ++i) {
        double ref = reference::distance(set, pts[i]);
        ASSERT_NEAR(got.d[i], ref, 1e-5 * (1 + std::fabs(ref))) << i;
        ASSERT_EQ(got.d[i], want.d[i]) << i;  // the same float operations as the unrolled union
        ASSERT_EQ(got.d_mat[i], want.d_mat[i]) << i;
        ASSERT_EQ(got.mat[i], want.mat[i]) << i;
      }
    }
  }
}

}  // namespace
}  // namespace sdfc
