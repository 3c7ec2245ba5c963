// Miss rate of every fractal node's estimator on the views it is shown in:
// camera rays through a grid of pixels of each example scene, marched over
// the scene's own field (the reference evaluator, which the conformance
// suite ties to the kernel) with the scene's own march settings.
//
// A ray counts for fractal node F when the first surface a fine
// conservative march finds (steps of 0.05 x d, then bisection, looking for
// d < hit_epsilon / 10) belongs to F: with F replaced by nothing the scene
// is no longer near that point. It is a miss when the renderer's march
// (step d x step_factor, hit at d < hit_epsilon x pixel footprint) ends
// beyond that surface or never hits. The target for the default
// estimator of every node is a miss rate below 0.1 %.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "e2e_support.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::e2e {
namespace {

using test::add;
using test::mul;

// The module with node `gone` replaced by a sphere far away: the scene
// without that fractal (an intersection with it becomes far too).
ir::Module without(const ir::Module& m, ir::NodeId gone) {
  ir::Module out = m;
  out.graph = std::make_shared<ir::Graph>();
  out.graph->expressions = m.graph->expressions;
  ir::Builder b(*out.graph);
  std::unordered_map<ir::NodeId, ir::NodeId> mapped;
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (id == gone) {
      ir::NodeId s = b.make(ir::Kind::Sphere, {1}, {});
      mapped[id] = b.make(ir::Kind::Translate, {1e5, 0, 0}, {s});
      continue;
    }
    std::vector<ir::NodeId> kids;
    for (ir::NodeId c : n.children) kids.push_back(mapped.at(c));
    ir::NodeId nid = b.copy(n, std::move(kids));
    out.graph->mutable_node(nid).props = n.props;
    mapped[id] = nid;
  }
  out.root = mapped.at(m.root);
  return out;
}

struct Tally {
  int hits = 0, misses = 0;
};

// Sample grid: every kStride-th pixel of the example's own resolution (at
// 1280x720 about 6400 rays per example, 1 to 2 s each).
constexpr int kStride = 12;


// The examples whose fractal is built from expr steps, which the CPU
// reference evaluates too slowly for ctest (several minutes each). Their
// instantiation is DISABLED_: bench/presets runs it for its table
// (e2e_tests --gtest_also_run_disabled_tests --gtest_filter='*ExampleMissRate*/menger_smooth').
std::vector<std::string> expr_examples() {
  std::vector<std::string> v;
  for (const char* f : {"mandelbulb_power_2", "box_fold_bulb_pow2", "eiffie_msltoe", "menger_smooth", "bulb2_expr"})
    v.push_back((std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / "formulas" / (std::string(f) + ".yaml")).string());
  return v;
}

std::vector<std::string> fractal_examples() {
  std::vector<std::string> v;
  std::vector<std::filesystem::path> scenes = example_scenes();
  // and the formula chains' and presets' examples, but for expr_examples()
  // (bulb2_expr's image is also held to bulb2's, tests/e2e/formula_image_test.cpp)
  for (const char* f : {"mandelbox_chain", "mandelbulb_chain", "mandelbulb_jacobian", "bulb2", "preset_mandelbox",
                        "preset_mandelbulb", "menger_sponge", "sierpinski_preset", "kaleidoscopic_ifs", "pseudo_kleinian",
                        "amazing_surf", "icosa_ifs", "xenodreambuie", "koch", "abox_mod11", "amazing_surf_mod2",
                        "amazing_surf_mod4", "abox_mod15", "menger_mod1", "menger3", "menger_cross_kifs",
                        "jos_kleinian", "julia_preset",
                        "quaternion", "hypercomplex", "aexion",
                        "hybrid_preset", "generalized_fold_box", "amazing_ifs", "newton_pow3"})
    scenes.push_back(std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / "formulas" / (std::string(f) + ".yaml"));
  for (const auto& p : scenes) {
    ir::Module m = build_module(load_yaml_file(p.string()), p.string());
    for (ir::NodeId id : m.graph->postorder(m.root))
      if (ir::info(m.graph->node(id).kind).category == ir::Category::Fractal) {
        v.push_back(p.string());
        break;
      }
  }
  return v;
}

struct NodeTally {
  ir::NodeId node;
  Tally tally;
};

// Camera rays through every kStride-th pixel; per fractal node, the rays
// whose first surface is its own, and the misses among them.
std::vector<NodeTally> measure(const ir::Module& m) {
  const ir::MarchSettings& s = m.plan.march;
  CameraRays cam(m.plan.camera, s.width, s.height);
  std::vector<NodeTally> out;
  std::vector<ir::Module> rest;  // the scene without each fractal
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (ir::info(m.graph->node(id).kind).category == ir::Category::Fractal) {
      out.push_back({id, {}});
      rest.push_back(without(m, id));
    }
  auto f = [&](const V3& p) { return reference::distance(m, p); };
  for (int y = kStride / 2; y < s.height; y += kStride)
    for (int x = kStride / 2; x < s.width; x += kStride) {
      V3 dir = cam.direction(x, y);
      auto at = [&](double t) { return add(cam.origin, mul(dir, t)); };
      auto eps = [&](double t) { return s.hit_epsilon * cam.pixel_angle * std::max(t, 1e-4); };
      // Conservative march, then bisection to the first point below eps / 10.
      double t = 0, prev = 0, t_first = -1;
      for (int i = 0; i < 2000000 && t < s.max_distance; ++i) {
        double d = f(at(t));
        if (d < 0.1 * eps(t)) {
          double lo = prev, hi = t;
          for (int b = 0; b < 40; ++b) {
            double mid = 0.5 * (lo + hi);
            (f(at(mid)) < 0.1 * eps(mid) ? hi : lo) = mid;
          }
          t_first = hi;
          break;
        }
        prev = t;
        t += std::max(0.05 * d, 0.025 * eps(t));
      }
      if (t_first < 0) continue;
      // Whose surface: the fractal whose removal takes the scene away from it.
      const V3 hit = at(t_first);
      int owner = -1;
      for (size_t k = 0; k < out.size(); ++k)
        if (reference::distance(rest[k], hit) > 10 * eps(t_first)) owner = int(k);
      if (owner < 0) continue;
      ++out[owner].tally.hits;
      TraceResult r = trace_reference(m, cam, dir);
      if (!r.hit || r.t > t_first + 2 * eps(t_first)) ++out[owner].tally.misses;
    }
  return out;
}

double rate(const Tally& t) { return t.hits ? double(t.misses) / t.hits : 0; }

class ExampleMissRate : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleMissRate, DefaultEstimatorsMissFewerThanOnePerMille) {
  const std::string path = GetParam();
  ir::Module m = build_module(load_yaml_file(path), path);
  std::vector<NodeTally> nodes = measure(m);
  ASSERT_FALSE(nodes.empty());
  const std::string file = std::filesystem::path(path).filename().string();
  for (const auto& [id, tally] : nodes) {
    const ir::Node& n = m.graph->node(id);
    fmt::print("[example-miss-rate] {:<18} {:<11} line {:3}  rays on it {:5}  misses {:3}  miss rate {:.3f} %\n", file,
               ir::info(n.kind).name, n.loc.line, tally.hits, tally.misses, 100 * rate(tally));
    SCOPED_TRACE(fmt::format("{} line {}", ir::info(n.kind).name, n.loc.line));
    EXPECT_GE(tally.hits, 50) << "too few sampled rays meet this fractal to measure anything";
    EXPECT_LT(rate(tally), 0.001) << "the estimator passes surfaces on its example view";
  }
}

// Every `de:` method of the Mandelbulb and the Mandelbox on their example
// views (the numbers to set beside bench/de_methods' render times). The
// default (analytic) is held to the 0.1 %, the others are recorded
// and must stay below 0.5 % (potential passes 3 of 2833 rays, 0.11 %).
struct MethodRun {
  std::string scene, key, method;
};
void PrintTo(const MethodRun& r, std::ostream* os) { *os << r.scene << " de: " << r.method; }

std::vector<MethodRun> method_runs() {
  std::vector<MethodRun> v;
  for (const char* m : {"analytic", "gradient", "potential", "sinh"})
    v.push_back({"mandelbulb.yaml", "scene.union.0.mandelbulb.de", m});
  for (const char* m : {"analytic", "jacobian"}) v.push_back({"mandelbox.yaml", "scene.mandelbox.de", m});
  return v;
}

class ExampleMissRateMethods : public ::testing::TestWithParam<MethodRun> {};

TEST_P(ExampleMissRateMethods, OnItsExampleView) {
  const MethodRun& run = GetParam();
  const std::string path = (std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / run.scene).string();
  SourceValue doc = load_yaml_file(path);
  apply_overrides(doc, {fmt::format("{}={}", run.key, run.method)});
  ir::Module m = build_module(doc, path);
  std::vector<NodeTally> nodes = measure(m);
  ASSERT_EQ(nodes.size(), 1u);
  const Tally& t = nodes[0].tally;
  fmt::print("[example-miss-rate] {:<18} de: {:<9}  rays on it {:5}  misses {:3}  miss rate {:.3f} %\n", run.scene,
             run.method, t.hits, t.misses, 100 * rate(t));
  EXPECT_GE(t.hits, 50);
  EXPECT_LT(rate(t), run.method == "analytic" ? 0.001 : 0.005);
}

INSTANTIATE_TEST_SUITE_P(Methods, ExampleMissRateMethods, ::testing::ValuesIn(method_runs()), [](const auto& info) {
  return std::filesystem::path(info.param.scene).stem().string() + "_" + info.param.method;
});

std::string example_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string n = std::filesystem::path(info.param).stem().string();
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleMissRate, ::testing::ValuesIn(fractal_examples()), example_name);
INSTANTIATE_TEST_SUITE_P(DISABLED_ExprExamples, ExampleMissRate, ::testing::ValuesIn(expr_examples()), example_name);

}  // namespace
}  // namespace sdfc::e2e
