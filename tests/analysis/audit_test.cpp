// sdfc audit finds the failure modes of sphere tracing where they exist, and
// stays quiet where the field keeps its promises.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include <algorithm>

#include "scene_text.hpp"
#include "sdfc/analysis/audit.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

analysis::AuditReport audit_text(const std::string& yaml) {
  return analysis::audit(passes::run_pipeline(test::lower_text(yaml)));
}

const analysis::NodeAudit& find(const analysis::AuditReport& r, const std::string& kind) {
  for (const auto& n : r.nodes)
    if (n.kind == kind) return n;
  throw std::runtime_error("no node " + kind);
}

TEST(Audit, ExactPrimitivesKeepTheirPromises) {
  auto r = audit_text(
      "scene:\n  union:\n    - sphere: {radius: 0.7}\n    - {box: {size: [1, 0.5, 0.3], radius: 0.05}, translate: [2, 0, 0]}\n"
      "    - {torus: {major_radius: 0.5, minor_radius: 0.1}, rotate: [40, 10, 0], translate: [0, 2, 0]}\n");
  EXPECT_FALSE(r.any_warning()) << analysis::format_table(r);
  for (const auto& n : r.nodes) {
    EXPECT_LE(n.measured_slope, 1.0 + 1e-9) << n.kind;  // exact fields are 1-Lipschitz
    EXPECT_GT(n.measured_slope, 0.9) << n.kind;          // and the test does measure something
    EXPECT_GT(n.rays, 10) << n.kind;
    EXPECT_EQ(n.overshoots, 0) << n.kind;
    EXPECT_EQ(n.nonfinite, 0) << n.kind;
    EXPECT_EQ(n.recommended_step_factor, 1.0) << n.kind;
  }
}

// Twist and displacement without the Lipschitz correction overshoot; the
// audit sees it and recommends a step factor it has verified by re-marching.
TEST(Audit, DetectsUncorrectedTwistAndDisplacement) {
  constexpr const char* scene =
      "render: {{lipschitz_correction: {}}}\nscene:\n  union:\n"
      "    - {{box: {{size: [1.0, 0.3, 2.0]}}, twist: {{axis: z, rate: 3}}}}\n"
      "    - {{sphere: {{radius: 0.7}}, displace: {{expr: \"0.1*sin(15*x)*sin(15*y)*sin(15*z)\"}}, translate: [2, 0, 0]}}\n";
  auto raw = audit_text(fmt::format(fmt::runtime(scene), "false"));
  for (const char* k : {"twist", "displace"}) {
    const auto& n = find(raw, k);
    EXPECT_TRUE(n.warning) << k;
    EXPECT_GT(n.overshoot_rate(), 0.05) << k;
    EXPECT_GT(n.measured_slope, 1.5) << k;
    EXPECT_LT(n.recommended_step_factor, 1.0) << k;
    EXPECT_GT(n.recommended_step_factor, 0.02) << k;
  }
  auto corrected = audit_text(fmt::format(fmt::runtime(scene), "true"));
  EXPECT_FALSE(corrected.any_warning()) << analysis::format_table(corrected);
}

// Seed 001 part VII: the scalar DE of a non-conformal Mandelbox overshoots.
TEST(Audit, DetectsTheNonConformalMandelboxOvershoot) {
  analysis::AuditOptions opt;
  opt.rays = 96;
  auto r = analysis::audit(
      passes::run_pipeline(test::lower_text("scene: {mandelbox: {scale: 2, iterations: 12, scale_xyz: [1.0, 1.6, 0.7]}}\n")),
      opt);
  const auto& box = find(r, "mandelbox");
  EXPECT_TRUE(box.warning);
  EXPECT_GT(box.overshoots, 0);
  auto conformal = analysis::audit(passes::run_pipeline(test::lower_text("scene: {mandelbox: {scale: 2, iterations: 12}}\n")), opt);
  EXPECT_EQ(find(conformal, "mandelbox").overshoots, 0) << analysis::format_table(conformal);
}

// Mandelbulber's power-2 bulb polynomial jumps across the z axis, and its
// estimate overshoots there: the warning names the step it trusts.
TEST(Audit, NamesTheChainStepAnOvershootingEstimateTrusts) {
  analysis::AuditOptions opt;
  opt.rays = 48;
  auto r = analysis::audit(
      passes::run_pipeline(test::lower_text("scene:\n  mandelbulb_power_2: {iterations: 12, bailout: 8}\n")), opt);
  const auto& f = find(r, "formula");
  ASSERT_TRUE(f.warning) << analysis::format_table(r);
  EXPECT_NE(f.note.find("the chain's expr (line 2)"), std::string::npos) << f.note;
}

TEST(Audit, LooksThroughBoundingBoxes) {
  // The root of this scene is wrapped in a bounding box by the passes; the
  // audit measures the geometry, so the box's switch is no "slope".
  auto r = audit_text("scene:\n  union:\n    - mandelbulb: {power: 8}\n    - {box: {size: [4, 4, 0.1]}, translate: [0, 0, -1.3]}\n");
  for (const auto& n : r.nodes) EXPECT_NE(n.kind, "bounded");
  EXPECT_FALSE(r.any_warning()) << analysis::format_table(r);
}

TEST(Audit, JsonCarriesEveryNode) {
  auto r = audit_text("scene: {union: [{sphere: {radius: 1}}, {box: {size: [1, 1, 1]}, translate: [3, 0, 0]}]}\n");
  std::string j = analysis::format_json(r);
  EXPECT_EQ(std::count(j.begin(), j.end(), '{'), 1 + long(r.nodes.size()));
  EXPECT_NE(j.find("\"kind\": \"sphere\""), std::string::npos) << j;
  EXPECT_NE(j.find("\"overshoot_rate\": 0"), std::string::npos) << j;
}

// The audit runs on every example. Exact and bound fields must keep their
// promise there; fractal estimates may overshoot somewhere in their region
// (the scalar Mandelbox DE does), which is what the audit is for: it reports
// the rate and a step factor instead.
TEST(Audit, RunsOnEveryExample) {
  int examples = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SDFC_SOURCE_DIR) + "/examples")) {
    if (e.path().extension() != ".yaml") continue;
    ++examples;
    analysis::AuditOptions opt;
    opt.lines = 32;
    opt.rays = 48;
    auto r = analysis::audit(build_module(load_scene_source(e.path().string(), {}), e.path().string()), opt);
    ASSERT_FALSE(r.nodes.empty()) << e.path();
    for (const auto& n : r.nodes) {
      EXPECT_EQ(n.nonfinite, 0) << e.path() << " " << n.kind;
      if (n.cls == ir::DistanceClass::Exact || n.cls == ir::DistanceClass::Bound) {
        EXPECT_EQ(n.overshoots, 0) << e.path() << "\n" << analysis::format_table(r);
      }
      if (n.overshoots > 0) {
        EXPECT_LT(n.recommended_step_factor, 1.0);
      }
    }
  }
  EXPECT_GE(examples, 2);
}

}  // namespace
}  // namespace sdfc
