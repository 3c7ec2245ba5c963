// The primitive catalogue, the domain operations and the blends,
// every OpenCL evaluator (SIMD width x precision) against the CPU reference
// at >= 1000 points per scene, with the Lipschitz correction on and off.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <random>

#include "conformance.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::conformance {
namespace {

struct DomainScene {
  std::string name;
  std::string geometry;  // a geometry node as YAML flow text
  double tol_scale = 1;  // trig-heavy domain maps lose a few float ulps more
};

// Every described kind's example, and the capsule's segment spelling.
std::vector<DomainScene> catalogue_scenes() {
  std::vector<DomainScene> v;
  for (const kinds::Description* d : kinds::all())
    if (d->kind != ir::Kind::Plane && ir::info(d->kind).category == ir::Category::Primitive)  // unbounded: it would stand in front of the rest of the group
      v.push_back({std::string(d->yaml), std::string(d->example)});
  v.push_back({"segment", "{segment: {a: [-0.4, 0.1, -0.3], b: [0.3, -0.2, 0.4], radius: 0.15}}"});
  return v;
}

std::vector<DomainScene> domain_scenes() {
  const std::string box = "{box: {size: [0.5, 0.4, 0.3], radius: 0.05}";
  std::vector<DomainScene> v = catalogue_scenes();
  v.insert(v.end(), {
      {"repeat_infinite", box + ", repeat: {period: [1.2, 1.0, 0]}}"},
      {"repeat_finite", box + ", repeat: {period: [0.7, 0.6, 0.5], count: [3, 2, 4]}}"},
      {"mirror", "{union: [{sphere: {radius: 0.3}, translate: [0.4, 0.2, 0.1]}], mirror: [x, y]}"},
      {"polar_repeat", "{union: [{box: {size: [0.3, 0.2, 0.4]}, translate: [0.8, 0, 0]}], polar_repeat: {axis: z, count: 7}}", 4},
      {"symmetry_tetrahedral", "{union: [{sphere: {radius: 0.25}, translate: [0.5, 0.4, 0.3]}], symmetry: tetrahedral}"},
      {"symmetry_octahedral", "{union: [{box: {size: [0.3, 0.2, 0.2]}, translate: [0.6, 0.3, 0.1]}], symmetry: octahedral}"},
      {"twist", "{box: {size: [0.5, 0.5, 2.0]}, twist: {axis: z, rate: 1.5}}", 8},
      {"bend", "{box: {size: [2.0, 0.3, 0.3]}, bend: {axis: x, rate: 0.6}}", 8},
      {"elongate", "{sphere: {radius: 0.3}, elongate: [0.6, 0, 0.2]}"},
      {"round", "{box: {size: [0.6, 0.6, 0.6]}, round: 0.1}"},
      {"onion", "{sphere: {radius: 0.7}, onion: [0.1, 0.03]}"},
      {"shell", "{box: {size: [1, 1, 1]}, shell: 0.1}"},
      {"displace", "{sphere: {radius: 0.7}, displace: {expr: \"0.08*sin(10*x)*sin(10*y)*sin(10*z)\"}}", 16},
      {"scale_xyz", "{torus: {major_radius: 0.5, minor_radius: 0.15}, scale: [1.5, 0.8, 2.0]}"},
      {"smooth_cubic", "{smooth_union: {radius: 0.3, kind: cubic, children: [{sphere: {radius: 0.5}}, {box: {size: [0.6, 0.6, 0.6]}, translate: [0.5, 0, 0]}]}}"},
      {"smooth_exponential", "{smooth_intersection: {radius: 0.1, kind: exponential, children: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}}"},
      {"chamfer_union", "{chamfer_union: {radius: 0.2, children: [{sphere: {radius: 0.5}}, {box: {size: [1.4, 0.3, 0.3]}}]}}"},
      {"round_difference", "{round_difference: {radius: 0.1, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.6}}]}}"},
      {"columns_union", "{columns_union: {radius: 0.3, steps: 4, children: [{box: {size: [1, 1, 0.2]}}, {box: {size: [0.2, 1, 1]}}]}}"},
      {"stairs_intersection", "{stairs_intersection: {radius: 0.2, steps: 3, children: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}}"},
  });
  return v;
}

// The scenes of a group side by side along x, 6 units apart, in one kernel
// (one kernel build per configuration instead of one per scene); points sit
// around each scene, so each one's code is what the union picks there.
struct Group {
  std::string name;
  std::vector<DomainScene> scenes;
};

std::vector<Group> groups() {
  std::vector<DomainScene> all = domain_scenes();
  const size_t n = catalogue_scenes().size();
  auto slice = [&](size_t a, size_t b) { return std::vector<DomainScene>(all.begin() + a, all.begin() + b); };
  std::vector<DomainScene> steep;  // the scenes whose L exceeds 1 (correction matters)
  for (const auto& s : all)
    if (s.name == "twist" || s.name == "bend" || s.name == "displace" || s.name == "chamfer_union" ||
        s.name == "round_difference" || s.name == "columns_union")
      steep.push_back(s);
  return {{"catalogue", slice(0, n)}, {"endless_repeat", slice(n, n + 1)}, {"domain", slice(n + 1, n + 14)},
          {"blends", slice(n + 14, all.size())}, {"steep", steep}};
}

struct Case {
  Group group;
  EvalConfig cfg;
  bool correct;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.group.name << " " << c.cfg.name(); }

// Every group at every configuration; the steep group also uncorrected.
std::vector<Case> cases() {
  std::vector<Case> out;
  for (const Group& g : groups())
    for (const EvalConfig& c : eval_configs()) {
      out.push_back({g, c, true});
      if (g.name == "steep") out.push_back({g, c, false});
    }
  return out;
}

class DomainConformance : public ::testing::TestWithParam<Case> {};

TEST_P(DomainConformance, MatchesReference) {
  const auto& [g, cfg, correct] = GetParam();
  std::vector<std::string> o = cfg.overrides();
  o.push_back(std::string("render.lipschitz_correction=") + (correct ? "true" : "false"));
  std::string yaml = "scene:\n  union:\n";
  std::vector<V3> pts;
  double tol_scale = 1;
  for (size_t i = 0; i < g.scenes.size(); ++i) {
    const DomainScene& sc = g.scenes[i];
    double x = 6.0 * double(i);
    yaml += fmt::format("    - {{union: [{}], translate: [{}, 0, 0]}}\n", sc.geometry, x);
    tol_scale = std::max(tol_scale, sc.tol_scale);
    // Points around this scene alone (its bounds, or a box where it is endless).
    ir::Module alone = test::compile_text("scene: " + sc.geometry + "\n", sc.name + ".yaml", o);
    ir::Box3 b = alone.graph->node(alone.root).props.bounds;
    V3 lo{-2.5, -2.5, -2.5}, hi{2.5, 2.5, 2.5};
    for (int k = 0; k < 3; ++k)
      if (std::isfinite(b.lo[k]) && std::isfinite(b.hi[k])) lo[k] = b.lo[k] - 0.4, hi[k] = b.hi[k] + 0.4;
    std::mt19937_64 rng(std::hash<std::string>{}(sc.name) ^ 0x9d0);
    int n = g.scenes.size() == 1 ? 1000 : 300;
    for (int k = 0; k < n; ++k) pts.push_back(test::add(test::uniform_in(rng, lo, hi), V3{x, 0, 0}));
  }
  ASSERT_GE(pts.size(), 1000u);
  ir::Module m = test::compile_text(yaml, g.name + ".yaml", o);
  Tolerance tol = kernel_tolerance(cfg.dbl);
  tol.abs *= tol_scale;
  tol.rel *= tol_scale;
  probe_and_compare(m, cfg, pts, tol);
}

INSTANTIATE_TEST_SUITE_P(Domain, DomainConformance, ::testing::ValuesIn(cases()), [](const auto& info) {
  return info.param.group.name + "_" + info.param.cfg.name() + (info.param.correct ? "" : "_uncorrected");
});

}  // namespace
}  // namespace sdfc::conformance
