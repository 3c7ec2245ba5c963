// Object sets (sdfc/ir/object_set.hpp): which unions the gather_object_sets
// pass turns into data, that the reference evaluates a set as the union it
// replaces, that the kernel's hierarchy walk agrees with both at every SIMD
// width, and that a scene renders the same image either way, on PoCL.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <regex>
#include <sstream>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/ir/object_set.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/scene_caps.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "object_set_scenes.hpp"
#include "sdfc_test_support.hpp"
#include "sdfrt/renderer.hpp"

namespace sdfc {
namespace {

using test::kHead;
using test::scene;
using test::V3;
namespace os = ir::object_set;
constexpr size_t kThreshold = os::kLargeGroupSetMinPrims;  // this many scattered shapes are a set by either rule

// The scene as code: every pass but gather_object_sets.
ir::Module unrolled(const std::string& yaml) {
  ir::Module m = lower_scene(load_yaml_text(yaml, "test.yaml"), "test.yaml");
  for (const auto& p : passes::pipeline())
    if (p.name != "gather_object_sets") m = p.run(std::move(m));
  return m;
}

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

struct Case {
  std::string name;
  std::string yaml;
  double spread;
  bool seen_whole = true;  // the set sees the world's points: the camera's cone, bounded normals
};

// The set turned and moved as one: it sees other points than the camera's
// rays, so it is walked whole (a cone in the rays' frame would cull the
// items it must measure, and the rays would pass through them).
std::string turned(const std::string& yaml) {
  const std::string head = "scene:\n  union:\n";
  const size_t at = yaml.find(head) + head.size();
  std::string out = yaml.substr(0, at) + "    - union:\n";
  std::istringstream body(yaml.substr(at));
  for (std::string line; std::getline(body, line);) out += "    " + line + "\n";
  return out + "      rotate: [0, 0, 30]\n      translate: [0.5, 0, 0]\n";
}

std::vector<Case> cases() {
  return {{"flat", scene(300), 5},
          {"groups", scene(400, 4), 5},
          {"with_floor", scene(200, 1, "    - plane: {normal: [0, 0, 1], offset: -0.5}\n      material: c\n"), 5},
          {"coincident", scene(100, 1, "", 0.0), 1},
          {"far_apart", scene(100, 1, "", 2000), 2000},
          {"turned", turned(scene(200)), 6, false}};
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

// Camera rays march in their packet's cone (os_cone); `cones` false gives
// them none, as every other ray, so the set's distance is the whole union's.
// `edit` changes the kernel's source first.
sdfrt::FloatImage render(const ir::Module& m, const codegen::EmitOptions& opt = {16}, bool cones = true,
                         const std::function<std::string(const std::string&)>& edit = {}) {
  codegen::EmittedKernel k = codegen::emit_opencl(m, opt);
  if (!cones) k.source = std::regex_replace(k.source, std::regex(R"(os_camera_cone\([^;]*\);)"), "os_cone_none();");
  if (edit) k.source = edit(k.source);
  sdfrt::Renderer r(test::device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, "", k.scene_data});
  const int w = m.plan.march.width, h = m.plan.march.height;
  return r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h);
}

// Runs `check` on the case's set at packet widths 1, 16 and 64, with the
// material, normal and hit planes.
void each_width(const Case& c, const std::function<void(const ir::Module&, const codegen::EmitOptions&)>& check) {
  SCOPED_TRACE(c.name);
  ir::Module set = test::compile_text(c.yaml);
  for (int width : {1, 16, 64}) {
    SCOPED_TRACE(width);
    codegen::EmitOptions opt{width};
    opt.aovs = true;
    check(set, opt);
  }
}

// How many values (of every plane) differ between two renders of one size.
size_t differing(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  EXPECT_EQ(a.data.size(), b.data.size());
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.data.size(), b.data.size()); ++i) n += a.data[i] != b.data[i];
  return n;
}

// Without cones the set renders the unrolled union's image bit for bit,
// though its normals' taps cull the walk by the hit's distance
// (normal_tetrahedral_below) and the unrolled union's evaluate everything.
TEST(ObjectSetRender, SameImageAsTheUnrolledUnion) {
  for (const Case& c : cases()) {
    ir::Module code = unrolled(c.yaml);
    each_width(c, [&](const ir::Module& set, const codegen::EmitOptions& opt) {
      ASSERT_EQ(codegen::emit_opencl(set, opt).source.find("normal_tetrahedral_below(TIME_ARG pos") != std::string::npos,
                c.seen_whole);
      sdfrt::FloatImage a = render(set, opt, false), b = render(code, opt);
      size_t hits = 0;
      for (float v : a.plane(a.plane_index("hit"))) hits += v > 0;
      EXPECT_EQ(differing(a, b), 0u);
      if (c.name != "far_apart") {
        EXPECT_GT(hits, 0u);  // the objects are in view
      }
    });
  }
}

// In its cone a camera ray steps past the items beside its path, so it
// lands elsewhere within the hit band, but it hits what the whole union's
// march hits (the march without cones, which renders the unrolled union's
// image above): the two hit masks differ only on silhouettes (a pixel whose
// neighbour's hit differs without cones), never inside an object, at every
// packet width (one lane: the thinnest cone). The march measures the cone's
// items from a list (os_list) where it holds them all, and walks the
// hierarchy where not ("coincident": all 100 items in every cone).
TEST(ObjectSetRender, CameraConesHitWhatTheWholeUnionHits) {
  for (const Case& c : cases()) {
    each_width(c, [&](const ir::Module& set, const codegen::EmitOptions& opt) {
      const std::string k = codegen::emit_opencl(set, opt).source;
      ASSERT_EQ(k.find("= os_camera_cone(") != std::string::npos, c.seen_whole);
      ASSERT_EQ(k.find("os_list_gather(&list, cone, ") != std::string::npos, c.seen_whole);
      sdfrt::FloatImage a = render(set, opt), b = render(set, opt, false);
      auto ha = a.plane(a.plane_index("hit")), hb = b.plane(b.plane_index("hit"));
      const int w = a.width, h = a.height;
      auto edge = [&](int x, int y) {
        for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < w && v < h && (hb[size_t(v * w + u)] > 0) != (hb[size_t(y * w + x)] > 0)) return true;
        }
        return false;
      };
      size_t silhouette = 0;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if ((ha[size_t(y * w + x)] > 0) != (hb[size_t(y * w + x)] > 0)) {
            EXPECT_TRUE(edge(x, y)) << "pixel " << x << ", " << y;
            ++silhouette;
          }
      EXPECT_LT(silhouette, size_t(w * h) / 100);
    });
  }
}

// The hits' material and normal taps read the packet's list (os_union_shade)
// where it holds every item that could be nearest, and walk the set
// elsewhere: the same values as the walk's, bit for bit, at every width.
// A list of the camera's cone alone, made to shade, answers less often
// (none beside the packet's edges), still with the walk's values; without
// its check it gives others.
TEST(ObjectSetRender, HitsShadedFromTheListAsFromTheWalk) {
  auto replace = [](std::string k, const std::string& from, const std::string& to) {
    const size_t at = k.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? k : k.replace(at, from.size(), to);
  };
  auto walked = [&](const std::string& k) { return replace(k, "os_cone_shading(cone)", "os_cone_none()"); };
  auto narrow = [&](const std::string& k) {
    return replace(replace(k, "pixel_angle * 0.8660254f);", "0.0f);"), "if (c.cos_w == c.cos_a) c.list = 0;", "");
  };
  auto unchecked = [&](const std::string& k) {
    return replace(narrow(k), "if (M_ANY(live & (best > depth))) return false;", "");
  };
  size_t differ_unchecked = 0;
  for (const Case& c : cases()) {
    if (!c.seen_whole) continue;
    each_width(c, [&](const ir::Module& set, const codegen::EmitOptions& opt) {
      ASSERT_NE(codegen::emit_opencl(set, opt).source.find("= os_cone_shading(cone);"), std::string::npos);
      sdfrt::FloatImage want = render(set, opt, true, walked);
      EXPECT_EQ(differing(render(set, opt), want), 0u);
      EXPECT_EQ(differing(render(set, opt, true, narrow), want), 0u);
      differ_unchecked += differing(render(set, opt, true, unchecked), want);
    });
  }
  EXPECT_GT(differ_unchecked, 0u);
}

}  // namespace
}  // namespace sdfc
