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

// The camera packets' gather (os_list_gather) reads the hierarchy through
// its own nodes: every leaf of the walk's hierarchy once, in the walk's
// order, each under balls that hold its box; and a ball about each item
// that holds its shapes' balls as the gather measures them.
TEST(ObjectSetPack, GatherHierarchyHoldsEveryLeafInTheWalksOrder) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<os::Item> items(777);
  for (size_t i = 0; i < items.size(); ++i) {
    items[i].blend = i % 3 == 0 ? 0.1 : 0;
    for (size_t k = 0; k < (i % 3 == 0 ? 3u : 1u); ++k) {
      os::Prim p;
      p.type = (i + k) % 2 ? os::kBox : os::kSphere;
      p.center = {40 * u(rng), 40 * u(rng), 5 * u(rng)};
      p.size = {0.3 + 0.2 * u(rng), 0.3 + 0.2 * u(rng), 0.3 + 0.2 * u(rng)};
      items[i].prims.push_back(p);
    }
  }
  const std::vector<double> q = os::pack(items, 0);
  const os::View v{q};
  std::vector<size_t> walk, gathered;  // leaves, depth first, left before right
  auto descend = [&](auto& self, size_t n) -> void {
    if (v.node(n)[7] > 0) return walk.push_back(n);
    self(self, n + 1), self(self, size_t(v.node(n)[6]));
  };
  descend(descend, 0);
  auto holds = [&](const double* g, size_t k, const double* box) {
    const double r = g[3 * os::kGatherWidth + k];
    for (int corner = 0; corner < 8; ++corner) {
      double d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += std::pow(box[(corner >> a & 1) * 3 + a] - g[a * os::kGatherWidth + k], 2);
      if (std::sqrt(d2) > r) return false;
    }
    return true;
  };
  const double* gather = q.data() + os::kHeader + v.gather_at();
  // each slot's ball holds the boxes of the leaves below it
  auto visit = [&](auto& self, size_t g, std::vector<std::pair<const double*, size_t>> above) -> void {
    const double* node = gather + g * os::kGatherFloats;
    for (size_t k = 0; k < size_t(os::kGatherWidth); ++k) {
      if (node[3 * os::kGatherWidth + k] < 0) continue;
      const double ref = node[4 * os::kGatherWidth + k];
      auto path = above;
      path.push_back({node, k});
      if (ref < 0) {
        self(self, size_t(-1 - ref), path);
        continue;
      }
      gathered.push_back(size_t(ref));
      for (const auto& [n, slot] : path) ASSERT_TRUE(holds(n, slot, v.node(size_t(ref)))) << ref;
    }
  };
  visit(visit, 0, {});
  EXPECT_EQ(gathered, walk);
  const size_t stride = v.items() + os::kItemBallPad;
  const double* balls = q.data() + os::kHeader + v.item_balls_at();
  for (size_t i = 0; i < v.items(); ++i) {
    const double* item = v.item(i);
    const double reach = (item[1] - 1) * 0.25 * item[2];
    for (size_t k = 0; k < size_t(item[1]); ++k) {
      const double* p = v.prim(size_t(item[0]) + k);
      const double radius = (p[0] == double(os::kSphere) ? p[4] : std::sqrt(p[4] * p[4] + p[5] * p[5] + p[6] * p[6])) + reach;
      const double apart = std::hypot(p[1] - balls[i], p[2] - balls[stride + i], p[3] - balls[2 * stride + i]);
      EXPECT_LE(apart + radius, balls[3 * stride + i]) << i;
    }
  }
  for (size_t i = v.items(); i < stride; ++i) EXPECT_LT(balls[3 * stride + i], -1e29);  // padding no cone reaches
  // the kernel's stack holds the deepest hierarchy the host builds
  const std::string k = codegen::emit_opencl(test::compile_text(scene(100)), {16}).source;
  ASSERT_NE(k.find("os_list_gather(&list, cone, "), std::string::npos);
  EXPECT_NE(k.find(fmt::format("#define OS_GATHER_STACK {}\n", os::kGatherStack)), std::string::npos);
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
