// The lower-bound property: sphere tracing a scene's distance (as the kernel
// computes it, through the reference evaluator, which the conformance suite
// ties to every OpenCL evaluator) never passes the first surface that a
// conservative march (small fixed steps, watching the sign) finds. For every
// primitive, domain operation and blend, with the Lipschitz correction on;
// and with it off, the steep twist and displacement must overshoot, so the
// test can fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene_text.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "surface_sampling.hpp"

namespace sdfc {
namespace {

using test::P3;

struct Scene {
  std::string name;
  std::string geometry;
};

const Scene kOwnScenes[] = {
    {"segment", "{segment: {a: [-0.4, 0.1, -0.3], b: [0.3, -0.2, 0.4], radius: 0.15}}"},
    {"repeat_finite", "{box: {size: [0.5, 0.4, 0.3], radius: 0.05}, repeat: {period: [0.7, 0.6, 0.5], count: [3, 2, 3]}}"},
    {"repeat_reaching", "{sphere: {radius: 0.45}, repeat: {period: [0.6, 0.6, 0], count: [4, 3, 1]}}"},
    {"mirror", "{union: [{sphere: {radius: 0.3}, translate: [0.4, 0.2, 0.1]}], mirror: [x, y]}"},
    {"polar_repeat", "{union: [{box: {size: [0.3, 0.2, 0.4]}, translate: [0.8, 0, 0]}], polar_repeat: {axis: z, count: 7}}"},
    {"symmetry_tetrahedral", "{union: [{sphere: {radius: 0.25}, translate: [0.5, 0.4, 0.3]}], symmetry: tetrahedral}"},
    {"symmetry_octahedral", "{union: [{box: {size: [0.3, 0.2, 0.2]}, translate: [0.6, 0.3, 0.1]}], symmetry: octahedral}"},
    {"twist", "{box: {size: [1.0, 0.3, 2.0]}, twist: {axis: z, rate: 3}}"},
    {"bend", "{box: {size: [2.0, 0.3, 0.3]}, bend: {axis: x, rate: 0.8}}"},
    {"elongate", "{sphere: {radius: 0.3}, elongate: [0.6, 0, 0.2]}"},
    {"round", "{box: {size: [0.6, 0.6, 0.6]}, round: 0.1}"},
    {"onion", "{difference: [{sphere: {radius: 0.7}, onion: [0.1, 0.03]}, {box: {size: [2, 2, 2]}, translate: [1, 1, 1]}]}"},
    {"shell", "{difference: [{box: {size: [1, 1, 1]}, shell: 0.1}, {sphere: {radius: 0.4}, translate: [0.5, 0.5, 0.5]}]}"},
    {"displace", "{sphere: {radius: 0.7}, displace: {expr: \"0.1*sin(15*x)*sin(15*y)*sin(15*z)\"}}"},
    {"scale_xyz", "{torus: {major_radius: 0.5, minor_radius: 0.15}, scale: [1.5, 0.8, 2.0]}"},
    {"smooth_polynomial", "{smooth_union: {radius: 0.3, children: [{sphere: {radius: 0.5}}, {box: {size: [0.6, 0.6, 0.6]}, translate: [0.5, 0, 0]}]}}"},
    {"smooth_cubic", "{smooth_union: {radius: 0.3, kind: cubic, children: [{sphere: {radius: 0.5}}, {box: {size: [0.6, 0.6, 0.6]}, translate: [0.5, 0, 0]}]}}"},
    {"smooth_exponential", "{smooth_difference: {radius: 0.1, kind: exponential, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.5}, translate: [0.5, 0.5, 0.5]}]}}"},
    {"chamfer_union", "{chamfer_union: {radius: 0.2, children: [{sphere: {radius: 0.5}}, {box: {size: [1.4, 0.3, 0.3]}}]}}"},
    {"chamfer_parallel", "{chamfer_union: {radius: 0.4, children: [{box: {size: [1, 1, 0.2]}}, {box: {size: [1, 1, 0.2]}, translate: [0, 0, 0.05]}]}}"},
    {"round_difference", "{round_difference: {radius: 0.1, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.6}}]}}"},
    {"round_intersection", "{round_intersection: {radius: 0.15, children: [{sphere: {radius: 0.7}}, {box: {size: [1, 1, 1]}}]}}"},
    {"columns_union", "{columns_union: {radius: 0.3, steps: 4, children: [{box: {size: [1, 1, 0.2]}}, {box: {size: [0.2, 1, 1]}}]}}"},
    {"columns_difference", "{columns_difference: {radius: 0.2, steps: 3, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.55}, translate: [0.5, 0, 0]}]}}"},
    {"stairs_union", "{stairs_union: {radius: 0.3, steps: 4, children: [{box: {size: [1, 1, 0.2]}}, {box: {size: [0.2, 1, 1]}}]}}"},
    {"stairs_intersection", "{stairs_intersection: {radius: 0.2, steps: 3, children: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}}"},
};

// Every described kind's example, then the scenes above.
const std::vector<Scene>& scenes() {
  static const std::vector<Scene> v = [] {
    std::vector<Scene> out;
    for (const kinds::Description* d : kinds::all())
      if (d->kind != ir::Kind::Plane && ir::info(d->kind).category == ir::Category::Primitive)  // unbounded: the rays' box would hold no first surface to find
        out.push_back({std::string(d->yaml), std::string(d->example)});
    out.insert(out.end(), std::begin(kOwnScenes), std::end(kOwnScenes));
    return out;
  }();
  return v;
}

ir::Module compile(const std::string& geometry, bool correct) {
  std::string yaml = std::string("render: {lipschitz_correction: ") + (correct ? "true" : "false") + "}\nscene: " + geometry + "\n";
  return passes::run_pipeline(test::lower_text(yaml));
}

struct MarchStats {
  int rays_with_surface = 0;
  int skipped = 0;     // the sphere tracer passed (or never reached) the first surface
  int false_hits = 0;  // it stopped where there is no surface
};

// Rays from a sphere around the bounds towards random points inside them.
MarchStats march(const ir::Module& traced, const ir::Module& truth, int rays) {
  const ir::Box3& b = truth.graph->node(truth.root).props.bounds;
  P3 lo{b.lo[0], b.lo[1], b.lo[2]}, hi{b.hi[0], b.hi[1], b.hi[2]};
  P3 c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  double radius = 0.5 * std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) + 0.5;
  std::vector<P3> targets = test::points_in(lo, hi, rays, 777);
  std::vector<P3> dirs = test::points_in({-1, -1, -1}, {1, 1, 1}, rays, 4242);
  const double h = 0.002, tmax = 2 * radius;
  MarchStats s;
  for (int r = 0; r < rays; ++r) {
    P3 u = dirs[r];
    double un = std::hypot(u[0], u[1], u[2]);
    P3 o{c[0] + radius * u[0] / un, c[1] + radius * u[1] / un, c[2] + radius * u[2] / un};
    P3 d{targets[r][0] - o[0], targets[r][1] - o[1], targets[r][2] - o[2]};
    double dn = std::hypot(d[0], d[1], d[2]);
    for (double& x : d) x /= dn;
    auto at = [&](double t) { return P3{o[0] + d[0] * t, o[1] + d[1] * t, o[2] + d[2] * t}; };
    // Conservative: the first sign change in steps of h.
    double first = -1;
    for (double t = 0; t < tmax; t += h)
      if (reference::distance(truth, at(t)) <= 0) {
        first = t;
        break;
      }
    if (first < 0) continue;
    ++s.rays_with_surface;
    double t = 0;
    bool hit = false;
    for (int i = 0; i < 20000 && t < tmax; ++i) {
      double dist = reference::distance(traced, at(t));
      if (dist < 1e-5) {
        hit = true;
        break;
      }
      t += dist;
    }
    if (hit && std::fabs(reference::distance(truth, at(t))) > 1e-3) ++s.false_hits;
    if (!hit || t > first + h) {
      ++s.skipped;
      if (std::getenv("SDFC_DEBUG_RAYS"))
        std::fprintf(stderr, "ray %d: first surface at t=%.5f, traced %s at t=%.5f\n", r, first, hit ? "hit" : "missed", t);
    }
  }
  return s;
}

class LowerBound : public ::testing::TestWithParam<Scene> {};

TEST_P(LowerBound, SphereTracingNeverPassesTheFirstSurface) {
  const Scene& sc = GetParam();
  ir::Module corrected = compile(sc.geometry, true), raw = compile(sc.geometry, false);
  MarchStats s = march(corrected, raw, 300);
  EXPECT_GT(s.rays_with_surface, 60) << sc.name;
  EXPECT_EQ(s.skipped, 0) << sc.name << ": " << s.skipped << " of " << s.rays_with_surface << " rays passed the surface";
  EXPECT_EQ(s.false_hits, 0) << sc.name << ": rays stopped away from the surface";
  // Where L <= 1 the correction changes nothing, and the raw field must hold too.
  if (raw.graph->node(raw.root).props.lipschitz <= 1 + 1e-9) {
    MarchStats r = march(raw, raw, 300);
    EXPECT_EQ(r.skipped, 0) << sc.name << " (uncorrected)";
  }
}

INSTANTIATE_TEST_SUITE_P(Domain, LowerBound, ::testing::ValuesIn(scenes()),
                         [](const auto& info) { return info.param.name; });

// Without the correction the steep twist and displacement overshoot: the
// property above is not vacuous.
TEST(LowerBoundUncorrected, SteepTwistAndDisplacementOvershoot) {
  for (const char* name : {"twist", "displace"}) {
    const Scene* sc = nullptr;
    for (const Scene& s : scenes())
      if (s.name == name) sc = &s;
    ir::Module raw = compile(sc->geometry, false);
    EXPECT_GT(raw.graph->node(raw.root).props.lipschitz, 1.5) << name;
    MarchStats s = march(raw, raw, 300);
    EXPECT_GT(s.skipped, 0) << name << ": the uncorrected march never overshot";
    std::printf("%s uncorrected: %d of %d rays passed the surface\n", name, s.skipped, s.rays_with_surface);
  }
}

}  // namespace
}  // namespace sdfc
