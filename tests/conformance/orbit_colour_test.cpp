// Orbit-trap colour values on the device against the CPU reference: for every
// fractal kind, the kernel's scene_trap (what an orbit-trap material reads at
// a hit) with `source: trap` and with `source: iteration` (the smooth
// iteration count), at points on rays just outside the surface, where the
// renderer evaluates it. Double kernels must match the double reference
// tightly; float orbits drift from the double ones (each step expands the
// rounding by the power or the scale, and near the surface the escape step
// itself can differ), so float must match on most points.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc_test_support.hpp"
#include "trap_probe.hpp"

namespace sdfc {
namespace {

using test::add;
using test::mul;
using test::V3;

struct Case {
  std::string name;
  std::string node;
  double radius;  // of a ball around the set
};

std::vector<Case> cases() {
  return {
      {"mandelbulb", "mandelbulb: {power: 8, iterations: 8}", 1.2},
      {"juliabulb", "mandelbulb: {power: 8, iterations: 8, julia: [0.35, -0.3, 0.2]}", 1.3},
      {"mandelbox", "mandelbox: {scale: -1.5, iterations: 12}", 4.5},
      {"julia", "julia: {c: [-0.2, 0.6, 0.2, 0.2], iterations: 12}", 1.6},
      {"julia_cubic", "julia: {c: [-0.4, 0.3, 0.2, 0.1], degree: 3, iterations: 10}", 1.6},
      {"menger", "menger: {iterations: 4}", 1.5},
      {"sierpinski", "sierpinski: {iterations: 8}", 1.5},
      {"kifs", "kifs: {symmetry: icosahedral, iterations: 8, rotate_before: {axis: [1, 0.3, 0], degrees: 14}}", 1.8},
      {"hybrid", "hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}], repeat: [1, 2], iterations: 9, bailout: 3}", 2},
  };
}

std::string scene(const Case& c, const char* source, bool dbl) {
  return fmt::format(
      "render: {{precision: {}}}\n"
      "materials: {{m: {{orbit_trap: {{palette: [[0, 0, 0], [1, 1, 1]], source: {}}}}}}}\n"
      "scene: {{{}, material: m}}\n",
      dbl ? "double" : "float", source, c.node);
}

class OrbitColour : public ::testing::TestWithParam<std::tuple<Case, int, bool>> {};

TEST_P(OrbitColour, TrapAndIterationMatchTheReference) {
  const auto& [c, width, dbl] = GetParam();
  for (const char* source : {"trap", "iteration"}) {
    SCOPED_TRACE(source);
    ir::Module m = test::compile_text(scene(c, source, dbl));
    std::mt19937_64 rng(std::hash<std::string>{}(c.name));
    std::vector<V3> pts = test::points_near_surface(m, c.radius, rng, 400, 1200, 12);
    ASSERT_GE(pts.size(), 1000u) << "too few rays met the set";
    std::vector<float> got = test::run_point_kernel(test::trap_probe_kernel(m, width), "trap_probe", pts, width);
    const ir::Node& f = test::fractal_of(m);
    const bool iteration = std::string(source) == "iteration";
    int close = 0, finite = 0;
    double lo = 1e30, hi = -1e30;
    for (size_t i = 0; i < pts.size(); ++i) {
      auto ref = reference::orbit_colour(f, pts[i]);
      ASSERT_TRUE(ref.has_value());
      double want = iteration ? ref->iteration : ref->trap;
      lo = std::min(lo, want), hi = std::max(hi, want);
      finite += std::isfinite(got[i]);
      close += std::fabs(got[i] - want) <= (dbl ? 1e-5 : 2e-3) + (dbl ? 1e-5 : 1e-2) * std::fabs(want);
    }
    double share = double(close) / pts.size();
    fmt::print("[orbit-colour] {:<12} {:<9} w{:<2} {:<6}: {} points, values {:.3g} .. {:.3g}, {:.2f} % match\n", c.name,
               source, width, dbl ? "double" : "float", pts.size(), lo, hi, 100 * share);
    EXPECT_EQ(finite, int(pts.size()));
    EXPECT_GE(share, dbl ? 0.995 : 0.9);
    // The fold fractals never escape: their iteration count is 1 everywhere;
    // Mandelbox orbits that start this near the set grow by only |scale| a
    // step and do not reach the escape radius in 12 steps either.
    const bool no_escape = c.name == "menger" || c.name == "sierpinski" || c.name == "kifs" || c.name == "mandelbox";
    if (iteration && no_escape) {
      EXPECT_EQ(lo, 1.0);
    } else {
      EXPECT_GT(hi - lo, 1e-3) << "a constant says nothing";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fractals, OrbitColour,
                         ::testing::Combine(::testing::ValuesIn(cases()), ::testing::Values(1, 8), ::testing::Bool()),
                         [](const auto& info) {
                           return fmt::format("{}_w{}_{}", std::get<0>(info.param).name, std::get<1>(info.param),
                                              std::get<2>(info.param) ? "double" : "float");
                         });

}  // namespace
}  // namespace sdfc
