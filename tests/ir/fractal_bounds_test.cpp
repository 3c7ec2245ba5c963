// Fractal bounds from the estimator (passes/fractal_bounds.cpp): tighter
// than the worst case, and still holding the whole surface. The surface is
// found by brute force: every point of a dense grid over the worst-case box
// where the reference estimator is below a small fraction of the grid step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene_text.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc {
namespace {

struct Case {
  const char* name;
  const char* node;   // the fractal, as YAML
  double worst;       // half-side of the worst-case cube (what the bounds were before)
  double slack = 0.15;  // how far (a share of `worst`) the bounds may reach past the surface
};

struct Found {
  ir::Box3 bounds;
  int surface = 0;       // grid points on the surface
  int outside = 0;       // of those, outside the bounds
  double reach = 0;      // the farthest |coordinate| of a surface point
};

Found measure(const Case& c, int n = 96) {
  ir::Module m = passes::run_pipeline(test::lower_text(std::string("scene: ") + c.node + "\n"));
  const ir::Graph& g = *m.graph;
  ir::NodeId id = m.root;
  for (ir::NodeId k : g.postorder(m.root))
    if (ir::info(g.node(k).kind).category == ir::Category::Fractal) id = k;
  Found f;
  f.bounds = g.node(id).props.bounds;
  const double h = 2 * c.worst / n, tau = 0.5 * h;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        reference::Vec3 p{-c.worst + i * h, -c.worst + j * h, -c.worst + k * h};
        if (reference::evaluate(g, id, p).distance >= tau) continue;
        ++f.surface;
        bool in = true;
        for (int a = 0; a < 3; ++a) {
          in = in && p[a] >= f.bounds.lo[a] && p[a] <= f.bounds.hi[a];
          f.reach = std::max(f.reach, std::fabs(p[a]));
        }
        f.outside += !in;
      }
  return f;
}

double half_side(const ir::Box3& b) {
  double r = 0;
  for (int a = 0; a < 3; ++a) r = std::max({r, -b.lo[a], b.hi[a]});
  return r;
}

class FractalBounds : public ::testing::TestWithParam<Case> {};

TEST_P(FractalBounds, HoldTheWholeSurfaceAndAreTighterThanTheWorstCase) {
  const Case& c = GetParam();
  Found f = measure(c);
  ASSERT_GT(f.surface, 20) << c.name << ": the grid found no surface";
  EXPECT_EQ(f.outside, 0) << c.name << ": surface points outside the bounds";
  double r = half_side(f.bounds);
  // Tight: not far past the farthest surface point found.
  EXPECT_LT(r, f.reach + c.slack * c.worst) << c.name;
  EXPECT_LE(r, c.worst * 1.0001) << c.name;
  std::printf("%-28s worst %.3g -> bounds [%.3g %.3g %.3g]..[%.3g %.3g %.3g] (surface reaches %.3g)\n", c.name, c.worst,
              f.bounds.lo[0], f.bounds.lo[1], f.bounds.lo[2], f.bounds.hi[0], f.bounds.hi[1], f.bounds.hi[2], f.reach);
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, FractalBounds,
    ::testing::Values(
        Case{"MandelboxDefaults", "{mandelbox: {}}", 10.5},
        Case{"MandelboxScale2", "{mandelbox: {scale: 2}}", 6.3},
        Case{"MandelboxExample", "{mandelbox: {scale: -1.5, min_radius: 0.5, fixed_radius: 1.0, iterations: 14}}", 10.5},
        Case{"MandelboxScale2Deep", "{mandelbox: {scale: 2, min_radius: 0.25, fixed_radius: 1, iterations: 16}}", 6.3},
        Case{"MandelboxJulia", "{mandelbox: {scale: 2, julia: [0.8, -0.4, 0.3]}}", 6.3, 0.2},
        Case{"MandelboxNonConformal", "{mandelbox: {scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], de: jacobian}}", 23.1},
        Case{"JuliaDefaults", "{julia: {}}", 1.5},
        Case{"JuliaCubic", "{julia: {c: [0.3, 0.5, 0.1, 0], degree: 3}}", 1.4},
        Case{"KifsDefaults", "{kifs: {}}", 1.77},
        Case{"KifsExample", "{kifs: {rotate_before: {axis: [1, 0.3, 0], degrees: 14}, rotate_after: {axis: [0, 0.2, 1], degrees: 22}}}", 1.77},
        Case{"KifsOctahedral", "{kifs: {symmetry: octahedral, scale: 3}}", 1.77},
        Case{"KifsIcosahedral", "{kifs: {symmetry: icosahedral, scale: 2.5}}", 1.77},
        Case{"KifsMenger", "{kifs: {symmetry: menger, scale: 3, iterations: 5}}", 1.77},
        Case{"HybridDefaults", "{hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}]}}", 10, 0.6},  // a weak estimator: the search stops at its budget
        Case{"HybridExample", "{hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}], repeat: [1, 2], bailout: 4}}", 4, 0.3}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace sdfc
