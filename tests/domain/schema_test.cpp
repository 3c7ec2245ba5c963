// Scene mistakes in domain operations and blends: located, explained errors.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

// The first error of a scene that must fail (lowering or the passes), as "line:col message".
std::string first_error(const std::string& scene) {
  try {
    passes::run_pipeline(test::lower_text(scene));
  } catch (const SceneError& e) {
    const Diagnostic& d = e.diagnostics().at(0);
    return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.message + " | " + d.hint;
  }
  return "";
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

TEST(DomainSchema, RepeatPeriodMustExceedTheShape) {
  std::string e = first_error("scene:\n  sphere: {radius: 0.6}\n  repeat: {period: [0.5, 1, 0]}\n");
  EXPECT_TRUE(has(e, "3:")) << e;
  EXPECT_TRUE(has(e, "along x the shape reaches 0.6")) << e;
}

TEST(DomainSchema, RepeatCountIsWhole) {
  EXPECT_TRUE(has(first_error("scene: {sphere: {radius: 0.2}, repeat: {period: [1, 1, 1], count: [2.5, 1, 1]}}\n"),
                  "not a whole number"));
  EXPECT_TRUE(has(first_error("scene: {sphere: {radius: 0.2}, repeat: {period: [0, 0, 0]}}\n"), "nothing repeats"));
}

TEST(DomainSchema, UnboundedDisplacementIsRefused) {
  std::string e = first_error("scene: {sphere: {radius: 1}, displace: {expr: \"x*x*x\"}}\n");
  EXPECT_TRUE(has(e, "cannot be bounded")) << e;
  std::string syntax = first_error("scene: {sphere: {radius: 1}, displace: {expr: \"0.1*sin(10*w)\"}}\n");
  EXPECT_TRUE(has(syntax, "w")) << syntax;
}

TEST(DomainSchema, MisspelledModifiersAndWords) {
  EXPECT_TRUE(has(first_error("scene: {box: {}, twsit: {rate: 1}}\n"), "twist")) << first_error("scene: {box: {}, twsit: {rate: 1}}\n");
  EXPECT_TRUE(has(first_error("scene: {box: {}, symmetry: cubic}\n"), "symmetry"));
  EXPECT_TRUE(has(first_error("scene: {box: {}, mirror: [x, w]}\n"), "mirror[1]"));
  EXPECT_TRUE(has(first_error("scene: {box: {}, twist: {axis: z}}\n"), "rate"));
}

TEST(DomainSchema, BlendKindsAndSteps) {
  EXPECT_TRUE(has(first_error("scene: {smooth_union: {radius: 0.1, kind: quartic, children: [{sphere: {}}]}}\n"), "kind"));
  EXPECT_TRUE(has(first_error("scene: {chamfer_union: {radius: 0.1, steps: 3, children: [{sphere: {}}]}}\n"), "steps"));
  EXPECT_EQ(first_error("scene: {stairs_difference: {radius: 0.1, steps: 3, children: [{box: {}}, {sphere: {radius: 0.6}}]}}\n"), "");
}

TEST(DomainSchema, SteepNodesAreMarkedForCorrection) {
  ir::Module m = passes::run_pipeline(test::lower_text("scene: {box: {size: [0.5, 0.5, 2]}, twist: {axis: z, rate: 2}}\n"));
  const ir::Props& p = m.graph->node(m.root).props;
  EXPECT_GT(p.lipschitz, 1.0);
  EXPECT_TRUE(p.corrected);
  EXPECT_EQ(p.cls, ir::DistanceClass::Lipschitz);
  ir::Module off = passes::run_pipeline(
      test::lower_text("render: {lipschitz_correction: false}\nscene: {box: {size: [0.5, 0.5, 2]}, twist: {axis: z, rate: 2}}\n"));
  EXPECT_FALSE(off.graph->node(off.root).props.corrected);
  // A corrected child reaches its parent as a bound with L = 1: the correction stays local.
  ir::Module u = passes::run_pipeline(test::lower_text(
      "scene:\n  union:\n    - {box: {size: [0.5, 0.5, 2]}, twist: {axis: z, rate: 2}}\n    - {sphere: {radius: 0.5}, translate: [3, 0, 0]}\n"));
  EXPECT_EQ(u.graph->node(u.root).props.lipschitz, 1.0);
  EXPECT_FALSE(u.graph->node(u.root).props.corrected);
}

}  // namespace
}  // namespace sdfc
