// --set path=value overrides edit the source tree before validation.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/source/overrides.hpp"

namespace sdfc {
namespace {

const char* kScene =
    "render: {width: 100}\n"
    "scene:\n"
    "  union:\n"
    "    - mandelbulb: {power: 8}\n"
    "    - sphere: {radius: 1}\n";

ir::Module lower_with(std::vector<std::string> sets) {
  SourceValue doc = load_yaml_text(kScene, "t.yaml");
  apply_overrides(doc, sets);
  return lower_scene(doc, "t.yaml");
}

TEST(Overrides, SetsExistingAndMissingValues) {
  ir::Module m = lower_with({"render.width=640", "render.height=360", "camera.fov=30"});
  EXPECT_EQ(m.plan.march.width, 640);
  EXPECT_EQ(m.plan.march.height, 360);
  EXPECT_DOUBLE_EQ(m.plan.camera.fov_degrees, 30);
}

TEST(Overrides, WalksListsByIndex) {
  ir::Module m = lower_with({"scene.union.0.mandelbulb.power=7"});
  bool found = false;
  for (ir::NodeId id = 0; id < m.graph->size(); ++id)
    if (m.graph->node(id).kind == ir::Kind::Mandelbulb) {
      EXPECT_DOUBLE_EQ(m.graph->node(id).params[0], 7);
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(Overrides, ValuesAreYaml) {
  ir::Module m = lower_with({"camera.position=[1, -4, 2]"});
  EXPECT_DOUBLE_EQ(m.plan.camera.position[1], -4);
}

TEST(Overrides, BadValueErrorPointsAtTheOverride) {
  try {
    lower_with({"render.width=abc"});
    FAIL();
  } catch (const SceneError& e) {
    const Diagnostic& d = e.diagnostics().front();
    EXPECT_EQ(*d.loc.file, "--set render.width");
    EXPECT_EQ(d.loc.column, 14);  // the value starts after "render.width="
    EXPECT_NE(d.message.find("expected a whole number"), std::string::npos) << d.str();
  }
}

TEST(Overrides, BadPaths) {
  SourceValue doc = load_yaml_text(kScene, "t.yaml");
  EXPECT_THROW(apply_override(doc, "scene.union.5.sphere.radius=1"), SceneError);
  EXPECT_THROW(apply_override(doc, "scene.union.x=1"), SceneError);
  EXPECT_THROW(apply_override(doc, "render.width.deeper=1"), SceneError);
  EXPECT_THROW(apply_override(doc, "novalue"), SceneError);
  EXPECT_THROW(apply_override(doc, "render..width=1"), SceneError);
}

TEST(Overrides, UnknownKeyCreatedByOverrideIsStillAnError) {
  EXPECT_THROW(lower_with({"render.widht=640"}), SceneError);
}

}  // namespace
}  // namespace sdfc
