// Materials across smooth blends: the OpenCL scene_material (the
// mixed albedo, specular, shininess and reflectivity) against the CPU
// reference's evaluate_material at points near the surface, for every
// smooth kind, nested under modifiers and hard operations.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "conformance.hpp"

namespace sdfc::conformance {
namespace {

const char* kMaterials =
    "materials:\n"
    "  red: {color: [0.9, 0.1, 0.1], specular: 0.1, shininess: 8, reflectivity: 0.0}\n"
    "  blue: {color: [0.1, 0.2, 0.9], specular: 0.7, shininess: 96, reflectivity: 0.5}\n"
    "  green: {color: [0.2, 0.8, 0.3], specular: 0.3, shininess: 24, reflectivity: 0.2}\n";

struct BlendScene {
  std::string name;
  std::string scene;  // the `scene:` body
};
void PrintTo(const BlendScene& s, std::ostream* os) { *os << s.name; }

std::vector<BlendScene> blend_scenes() {
  const std::string red = "{sphere: {radius: 0.8}, translate: [-0.6, 0, 0], material: red}";
  const std::string blue = "{sphere: {radius: 0.8}, translate: [0.6, 0, 0], material: blue}";
  const std::string box = "{box: {size: [0.7, 0.7, 0.7]}, material: red}";
  const std::string ball = "{sphere: {radius: 0.9}, translate: [0.4, 0.2, 0], material: blue}";
  const std::string green = "{torus: {major_radius: 0.7, minor_radius: 0.2}, translate: [0, 0, 0.7], material: green}";
  return {
      {"polynomial_union", fmt::format("  smooth_union: {{radius: 0.6, children: [{}, {}]}}\n", red, blue)},
      {"polynomial_intersection", fmt::format("  smooth_intersection: {{radius: 0.4, children: [{}, {}]}}\n", box, ball)},
      {"polynomial_difference", fmt::format("  smooth_difference: {{radius: 0.4, children: [{}, {}]}}\n", box, ball)},
      {"cubic_union_three", fmt::format("  smooth_union: {{radius: 0.5, kind: cubic, children: [{}, {}, {}]}}\n", red,
                                        blue, green)},
      {"exponential_union", fmt::format("  smooth_union: {{radius: 0.2, kind: exponential, children: [{}, {}]}}\n", red, blue)},
      {"exponential_intersection",
       fmt::format("  smooth_intersection: {{radius: 0.15, kind: exponential, children: [{}, {}]}}\n", box, ball)},
      {"cubic_difference", fmt::format("  smooth_difference: {{radius: 0.4, kind: cubic, children: [{}, {}]}}\n", box, ball)},
      // An outer material claims the unassigned torus; the blend sits under
      // round and a hard union with a chamfered pair and a repeated row.
      {"nested",
       "  union:\n"
       "    - smooth_union:\n"
       "        radius: 0.5\n"
       "        children:\n"
       "          - {sphere: {radius: 0.6}, material: red}\n"
       "          - {torus: {major_radius: 0.6, minor_radius: 0.15}, translate: [0.5, 0, 0]}\n"
       "      round: 0.05\n"
       "    - chamfer_union: {radius: 0.2, children: [{box: {size: [0.3, 0.3, 0.3]}, material: blue}, "
       "{sphere: {radius: 0.3}, translate: [0.3, 0, 0]}]}\n"
       "      translate: [0, 0, 1.3]\n"
       "    - smooth_union: {radius: 0.3, children: [{sphere: {radius: 0.2}, material: blue}, "
       "{box: {size: [0.3, 0.1, 0.1]}, material: red}]}\n"
       "      repeat: {period: [0.8, 0, 0], count: [3, 1, 1]}\n"
       "      translate: [0, 0, -1.3]\n"
       "  material: green\n"},
  };
}

class MaterialBlend : public ::testing::TestWithParam<BlendScene> {};

TEST_P(MaterialBlend, OpenCLMatchesReference) {
  const std::string yaml = std::string(kMaterials) + "scene:\n" + GetParam().scene;
  for (EvalConfig cfg : {EvalConfig{1, false}, EvalConfig{16, false}, EvalConfig{8, true}}) {
    SCOPED_TRACE(cfg.name());
    ir::Module m = test::compile_text(yaml, "blend.yaml", cfg.overrides());
    std::mt19937_64 rng(42);
    std::vector<V3> points;
    int mixed = 0;  // points where two materials both have a share > 5%
    while (points.size() < 600) {
      V3 p = test::to_float_point(test::uniform_in(rng, {-2, -2, -2}, {2, 2, 2}));
      reference::Sample s = reference::evaluate(*m.graph, m.root, p);
      if (std::fabs(s.distance) > 0.3) continue;
      int big = 0;
      for (const auto& [id, w] : s.shares) big += w > 0.05;
      mixed += big >= 2;
      points.push_back(p);
    }
    EXPECT_GE(mixed, 20) << "too few points in a blend's seam to test it";
    test::Probe probe(m, cfg.simd_width);
    auto got = probe.run_material(points);
    const double tol = cfg.dbl ? 2e-5 : 1e-3;
    int bad = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      reference::Look ref = reference::evaluate_material(m, points[i]);
      double want[6] = {ref.albedo[0], ref.albedo[1], ref.albedo[2], ref.specular, ref.shininess, ref.reflectivity};
      for (int c = 0; c < 6; ++c)
        if (std::fabs(got[i][c] - want[c]) > tol * (1 + std::fabs(want[c])) && ++bad <= 5)
          ADD_FAILURE() << fmt::format("at ({}, {}, {}) parameter {}: OpenCL {} reference {}", points[i][0], points[i][1],
                                       points[i][2], c, got[i][c], want[c]);
    }
    EXPECT_EQ(bad, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Blends, MaterialBlend, ::testing::ValuesIn(blend_scenes()),
                         [](const auto& info) { return info.param.name; });

// The reference's shares: they sum to 1, and far from a seam one child
// owns the point.
TEST(MaterialBlendOracle, SharesSumToOneAndArePureFarFromTheSeam) {
  ir::Module m = test::compile_text(std::string(kMaterials) + "scene:\n" + blend_scenes()[0].scene);
  for (double x = -1.5; x <= 1.5; x += 0.01) {
    reference::Sample s = reference::evaluate(*m.graph, m.root, {x, 0.1, 0.0});
    double sum = 0;
    for (const auto& [id, w] : s.shares) sum += w;
    if (!s.shares.empty()) {
      EXPECT_NEAR(sum, 1.0, 1e-9) << x;
    }
    // Spheres at x = -0.6 and 0.6: the distances differ by more than the
    // radius 0.6 beyond |x| ~ 0.31, where one material remains.
    if (std::fabs(x) > 0.33) {
      EXPECT_TRUE(s.shares.empty()) << x;
    }
  }
  reference::Look mid = reference::evaluate_material(m, {0, 0.1, 0});
  EXPECT_NEAR(mid.albedo[0], 0.5, 1e-6);  // half red 0.9, half blue 0.1
  EXPECT_NEAR(mid.shininess, 52, 1e-4);
}

}  // namespace
}  // namespace sdfc::conformance
