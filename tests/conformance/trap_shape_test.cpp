// Orbit-trap shapes (`orbit_trap.shape`) on the device against the CPU
// reference: for each shape other than the default and every kind of orbit
// (each stdlib trap function, and the hybrid's inline loop), the kernel's
// scene_trap at points just outside the surface against
// reference::orbit_colour with the same shape, in double (tight) and float
// (most points: float orbits drift from the double ones).
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

struct Fractal {
  std::string name, node;
  double radius;  // of a ball around the set
};

std::vector<Fractal> fractals() {
  return {
      {"mandelbulb", "mandelbulb: {power: 8, iterations: 8}", 1.2},
      {"mandelbulb_trig", "mandelbulb: {power: 7.5, iterations: 8}", 1.2},
      {"mandelbox", "mandelbox: {scale: -1.5, iterations: 12}", 4.5},
      {"julia", "julia: {c: [-0.2, 0.6, 0.2, 0.2], iterations: 12}", 1.6},
      {"menger", "menger: {iterations: 4}", 1.5},
      {"sierpinski", "sierpinski: {iterations: 8}", 1.5},
      {"kifs", "kifs: {symmetry: icosahedral, iterations: 8}", 1.8},
      {"hybrid", "hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}], repeat: [1, 2], iterations: 9, bailout: 3}", 2},
  };
}

struct Shape {
  std::string name, keys;
};

std::vector<Shape> shapes() {
  return {{"point", "shape: point, point: [0.3, -0.2, 0.5]"},
          {"plane", "shape: plane, normal: [0, 1, 1], point: [0, 0, 0.25]"},
          {"line", "shape: line, point: [0.1, 0, 0], direction: [1, 1, 0]"},
          {"sphere", "shape: sphere, point: [0, 0, 0.1], radius: 0.7"}};
}

std::string scene(const Fractal& f, const Shape& s, bool dbl) {
  return fmt::format(
      "render: {{precision: {}}}\n"
      "materials: {{m: {{orbit_trap: {{palette: [[0, 0, 0], [1, 1, 1]], {}}}}}}}\n"
      "scene: {{{}, material: m}}\n",
      dbl ? "double" : "float", s.keys, f.node);
}

class TrapShapes : public ::testing::TestWithParam<std::tuple<Fractal, Shape, bool>> {};

TEST_P(TrapShapes, KernelTrapMatchesTheReference) {
  const auto& [f, s, dbl] = GetParam();
  ir::Module m = test::compile_text(scene(f, s, dbl));
  const ir::TrapShape& shape = m.plan.materials.at(1).trap_shape;
  ASSERT_NE(shape.kind, ir::TrapShape::Kind::Cross);
  std::mt19937_64 rng(std::hash<std::string>{}(f.name + s.name));
  std::vector<V3> pts = test::points_near_surface(m, f.radius, rng, 300, 600, 6);
  ASSERT_GE(pts.size(), 500u) << "too few rays met the set";
  const int width = dbl ? 8 : 16;
  std::vector<float> got = test::run_point_kernel(test::trap_probe_kernel(m, width), "trap_probe", pts, width);
  int close = 0, finite = 0, moved = 0;
  double lo = 1e30, hi = -1e30;
  for (size_t i = 0; i < pts.size(); ++i) {
    double want = reference::orbit_colour(test::fractal_of(m), pts[i], shape)->trap;
    double cross = reference::orbit_colour(test::fractal_of(m), pts[i])->trap;
    lo = std::min(lo, want), hi = std::max(hi, want);
    finite += std::isfinite(got[i]);
    moved += std::fabs(want - cross) > 1e-3;
    close += std::fabs(got[i] - want) <= (dbl ? 1e-5 : 2e-3) + (dbl ? 1e-5 : 1e-2) * std::fabs(want);
  }
  double share = double(close) / pts.size();
  fmt::print("[trap-shape] {:<15} {:<6} {:<6}: {} points, values {:.3g} .. {:.3g}, {:.2f} % match\n", f.name, s.name,
             dbl ? "double" : "float", pts.size(), lo, hi, 100 * share);
  EXPECT_EQ(finite, int(pts.size()));
  EXPECT_GE(share, dbl ? 0.995 : 0.9);
  EXPECT_GT(hi - lo, 1e-3) << "a constant says nothing";
  EXPECT_GT(moved, int(pts.size()) / 2) << "the shape should change the trap from the default's";
}

// Every shape on every kind of orbit in double; in float on three of them.
std::vector<std::tuple<Fractal, Shape, bool>> params() {
  std::vector<std::tuple<Fractal, Shape, bool>> out;
  for (const Fractal& f : fractals())
    for (const Shape& s : shapes()) {
      out.emplace_back(f, s, true);
      if (f.name == "mandelbulb" || f.name == "mandelbox" || f.name == "hybrid") out.emplace_back(f, s, false);
    }
  return out;
}

void PrintTo(const Fractal& f, std::ostream* os) { *os << f.name; }
void PrintTo(const Shape& s, std::ostream* os) { *os << s.name; }

INSTANTIATE_TEST_SUITE_P(Shapes, TrapShapes, ::testing::ValuesIn(params()),
                         [](const auto& info) {
                           return fmt::format("{}_{}_{}", std::get<0>(info.param).name, std::get<1>(info.param).name,
                                              std::get<2>(info.param) ? "double" : "float");
                         });

}  // namespace
}  // namespace sdfc
