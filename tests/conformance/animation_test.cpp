// Animated scene values (expressions of time): every OpenCL evaluator
// against the CPU reference taken at the same time (reference::at_time), at
// several times, so a kernel that ignored time, or read it wrongly, fails
// wherever the scene has moved.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <random>

#include "conformance.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/reference/at_time.hpp"

namespace sdfc::conformance {
namespace {

struct AnimScene {
  std::string name;
  std::string yaml;
};

void PrintTo(const AnimScene& s, std::ostream* os) { *os << s.name; }

const char* kHead = "materials: {m1: {color: [0.9, 0.2, 0.1]}, m2: {color: [0.1, 0.3, 0.9]}}\n";

std::vector<AnimScene> anim_scenes() {
  return {
      {"catalogue",
       "scene:\n  union:\n"
       "    - {cone: {radius: \"0.3 + 0.1*sin(time)\", height: 0.6}, translate: [-0.8, -0.8, 0], material: m1}\n"
       "    - {round_cone: {height: \"0.6 + 0.1*cos(time)\", bottom_radius: 0.25, top_radius: 0.1}, translate: [0.8, -0.8, 0]}\n"
       "    - {link: {length: \"0.3 + 0.2*sin(time)\", major_radius: 0.3, minor_radius: 0.08}, translate: [0, 0.8, 0], material: m2}\n"
       "    - {box_frame: {size: [\"0.6 + 0.2*sin(time)\", 0.6, 0.6], edge: 0.06}, translate: [-0.8, 0.8, 0]}\n"
       "    - {pyramid: {base: 0.6, height: \"0.6 + 0.2*sin(2*time)\"}, translate: [0.8, 0.8, 0]}\n"
       "    - {ellipsoid: {radii: [0.3, \"0.2 + 0.1*cos(time)\", 0.2]}, translate: [0, 0, 0.7]}\n"
       "    - {triangle: {thickness: \"0.05 + 0.04*sin(time)\"}, translate: [0, -0.8, 0.6]}\n"},
      {"primitives",
       "scene:\n  union:\n"
       "    - {sphere: {radius: \"0.35 + 0.1*sin(time)\"}, translate: [\"0.6*cos(time)\", 0, \"0.2*sin(2*time)\"], material: m1}\n"
       "    - {box: {size: [0.5, \"0.5 + 0.3*sin(time)\", 0.4], radius: \"0.05 + 0.02*cos(time)\"}, "
       "rotate: {axis: [0, 0, 1], degrees: \"40*time\"}, translate: [-0.6, 0, 0], material: m2}\n"
       "    - {torus: {major_radius: \"0.4 + 0.1*cos(3*time)\", minor_radius: 0.1}, rotate: [\"30*time\", 0, 10], "
       "translate: [0, 0.7, 0]}\n"
       "    - {cylinder: {radius: 0.2, height: \"0.6 + 0.2*sin(time)\"}, scale: \"1 + 0.3*sin(time)\", translate: [0, -0.7, 0]}\n"
       "    - {capsule: {a: [0, 0, -0.3], b: [\"0.3*sin(time)\", 0, 0.3], radius: 0.1}, translate: [0, 0, 0.8]}\n"},
      {"blend",
       "scene:\n  smooth_union:\n    radius: \"0.2 + 0.15*sin(time)\"\n    children:\n"
       "      - {sphere: {radius: 0.5}, translate: [\"0.3 + 0.2*cos(time)\", 0, 0], material: m1}\n"
       "      - {box: {size: [0.6, 0.6, 0.6]}, translate: [-0.35, 0, 0], material: m2}\n"},
      // The hg_sdf-style smooth blends (kind: cubic, exponential) take an
      // animated radius like the polynomial one.
      {"blend_kinds",
       "scene:\n  union:\n"
       "    - smooth_union: {kind: cubic, radius: \"0.2 + 0.15*sin(time)\", children: [{sphere: {radius: 0.4}, "
       "translate: [0.25, 0.5, 0], material: m1}, {box: {size: [0.5, 0.5, 0.5]}, translate: [-0.25, 0.5, 0], material: m2}]}\n"
       "    - smooth_difference: {kind: exponential, radius: \"0.15 + 0.1*cos(time)\", children: [{box: {size: [0.8, 0.6, "
       "0.6]}, translate: [0, -0.5, 0]}, {sphere: {radius: 0.35}, translate: [0.3, -0.5, 0.2]}]}\n"},
      {"mandelbulb",
       "scene:\n  mandelbulb: {power: \"8 + 0.5*sin(time)\", iterations: 8, bailout: \"2 + 0.5*cos(time)\"}\n"
       "  rotate: {axis: [1, 1, 0], degrees: \"25*time\"}\n"},
      {"menger",
       "scene:\n  menger: {iterations: 3, scale: \"3 + 0.5*sin(time)\"}\n  translate: [0, 0, \"0.1*time\"]\n"},
      {"displace",
       "scene:\n  sphere: {radius: 0.8}\n  displace: {expr: \"0.06*sin(8*x + 2*time)*sin(8*y)*sin(8*z - time)\"}\n"},
  };
}

class AnimationConformance : public ::testing::TestWithParam<std::tuple<AnimScene, EvalConfig>> {};

TEST_P(AnimationConformance, MatchesReferenceAtEveryTime) {
  const auto& [sc, cfg] = GetParam();
  ir::Module m = test::compile_text(kHead + sc.yaml, sc.name + ".yaml", cfg.overrides());
  ASSERT_TRUE(m.graph->animated(m.root));
  std::mt19937_64 rng(7);
  std::vector<V3> points;
  for (int i = 0; i < 1500; ++i) points.push_back(test::uniform_in(rng, {-1.4, -1.4, -1.4}, {1.4, 1.4, 1.4}));
  for (auto& p : points) p = test::to_float_point(p);
  // The times are floats, as the kernel receives them.
  for (double t : {0.0, 0.75, 2.5, 11.0}) {
    SCOPED_TRACE(fmt::format("time {}", t));
    // The scene must have moved since time 0, or this time checks nothing new.
    if (t > 0) {
      ir::Module now = reference::at_time(m, t), start = reference::at_time(m, 0);
      int moved = 0;
      for (const auto& p : points) moved += std::fabs(reference::distance(now, p) - reference::distance(start, p)) > 1e-3;
      EXPECT_GT(moved, 100);
    }
    // Fractal estimators are ill-conditioned inside; the suite's fractal tolerance.
    Tolerance tol = kernel_tolerance(cfg.dbl);
    if (sc.name == "mandelbulb" || sc.name == "menger") tol = cfg.dbl ? Tolerance{1e-9, 0x1p-23} : Tolerance{2e-4, 2e-3, 5e-3, 0.5};
    probe_and_compare(m, cfg, points, tol, {}, t);
  }
}

INSTANTIATE_TEST_SUITE_P(Animation, AnimationConformance,
                         ::testing::Combine(::testing::ValuesIn(anim_scenes()), ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) {
                           return std::get<0>(info.param).name + "_" + std::get<1>(info.param).name();
                         });

// A whole-number power that is animated takes the trig formula: the
// trig-free one is specialised to one power.
TEST(AnimationCodegen, AnimatedIntegerPowerUsesTheTrigFormula) {
  ir::Module still = test::compile_text("scene: {mandelbulb: {power: 8}}\n");
  ir::Module moving = test::compile_text("scene: {mandelbulb: {power: \"8 + 0*time\"}}\n");
  std::string a = codegen::emit_opencl(still, {16}).source, b = codegen::emit_opencl(moving, {16}).source;
  EXPECT_NE(a.find("de_mandelbulb_int("), std::string::npos);
  EXPECT_EQ(b.find("de_mandelbulb_int("), std::string::npos);
  EXPECT_NE(b.find("de_mandelbulb(p"), std::string::npos) << b;
  EXPECT_NE(b.find("const scalar time = (scalar)frame[25];"), std::string::npos);
  EXPECT_EQ(a.find("(scalar)frame[25]"), std::string::npos) << "a static scene reads no time";
}

// Static expressions fold to literals: the kernel holds the number.
TEST(AnimationCodegen, StaticExpressionsFoldToLiterals) {
  ir::Module m = test::compile_text("scene: {sphere: {radius: \"0.5 + 2*0.25\"}}\n");
  EXPECT_FALSE(m.graph->animated(m.root));
  std::string src = codegen::emit_opencl(m, {1}).source;
  EXPECT_NE(src.find("sd_sphere(p, 1.0f)"), std::string::npos);
}

}  // namespace
}  // namespace sdfc::conformance
