// Diagnostics of the front end: their format, several at once, hints.
#include <gtest/gtest.h>

#include "scene_text.hpp"

namespace sdfc {
namespace {

using test::errors_of;

// One file per mistake lives in tests/bad_scenes/ (run through `sdfc check`);
// these tests cover what a single file cannot show.

TEST(SceneErrors, FormatsAsFileLineColumn) {
  auto diags = errors_of("scene:\n  union:\n    - sphre: {radius: 1}\n");
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].str(), "t.yaml:3:7: error: unknown node kind 'sphre' (did you mean 'sphere'?)");
}

TEST(SceneErrors, ReportsIndependentMistakesTogether) {
  auto diags = errors_of("camera: {fov: 400}\nrender: {width: -1}\nscene: {sphere: {radius: -1}}\n");
  ASSERT_EQ(diags.size(), 3u);
  EXPECT_EQ(diags[0].loc.line, 1);
  EXPECT_EQ(diags[1].loc.line, 2);
  EXPECT_EQ(diags[2].loc.line, 3);
}

TEST(SceneErrors, NoSuggestionForFarOffWords) {
  auto diags = errors_of("scene: {xyzzyq: {}}\n");
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].hint.find("did you mean"), std::string::npos) << diags[0].hint;
}

TEST(SceneFiles, MissingFileAndDirectory) {
  try {
    load_yaml_file("/nonexistent/scene.yaml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.yaml: error: no such file"), std::string::npos) << e.what();
  }
  try {
    load_yaml_file(SDFC_SOURCE_DIR);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

TEST(SceneDefaults, EverythingButSceneHasADefault) {
  ir::Module m = test::lower_text("scene: {sphere: {radius: 1}}\n");
  EXPECT_EQ(m.plan.march.width, 1280);
  EXPECT_EQ(m.plan.march.max_steps, 256);
  EXPECT_DOUBLE_EQ(m.plan.camera.fov_degrees, 45);
  EXPECT_EQ(m.plan.materials.size(), 1u);  // the default material
  EXPECT_GE(m.plan.lights.size(), 2u);     // a key light and the ambient fill
}

}  // namespace
}  // namespace sdfc
