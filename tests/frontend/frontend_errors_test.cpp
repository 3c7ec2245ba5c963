// Diagnostics of the front end: their format, several at once, hints.
#include <gtest/gtest.h>

#include "scene_text.hpp"

namespace sdfc {
namespace {

using test::errors_of;

struct Case {
  const char* name;
  const char* scene;
  int line, column;
  const char* message;  // fragment of the message
  const char* hint;     // fragment of the hint ("" = any)
};

const Case kCases[] = {
    {"unknown_kind", "scene:\n  union:\n    - sphre: {radius: 1}\n", 3, 7, "unknown node kind 'sphre'", "did you mean 'sphere'?"},
    {"unknown_top_key", "camrea: {fov: 40}\nscene: {sphere: {radius: 1}}\n", 1, 1, "unknown key 'camrea'", "did you mean 'camera'?"},
    {"unknown_param", "scene: {sphere: {raduis: 1}}\n", 1, 18, "unknown key 'raduis' in sphere", "did you mean 'radius'?"},
    {"string_for_number", "scene: {sphere: {radius: abc}}\n", 1, 26, "sphere.radius: expected a number, got 'abc'", ""},
    {"quoted_number", "scene: {sphere: {radius: \"1\"}}\n", 1, 26, "expected a number", "remove the quotes"},
    {"vec2_for_vec3", "scene: {sphere: {radius: 1}, translate: [1, 2]}\n", 1, 41, "expected a list of 3 numbers", ""},
    {"negative_size", "scene: {box: {size: [1, -2, 1]}}\n", 1, 25, "box.size: expected a positive number, got -2", ""},
    {"zero_radius", "scene: {sphere: {radius: 0}}\n", 1, 26, "expected a positive number, got 0", ""},
    {"nan", "scene: {sphere: {radius: .nan}}\n", 1, 26, "is not a finite number", ""},
    {"inf", "scene: {sphere: {radius: .inf}}\n", 1, 26, "is not a finite number", ""},
    {"huge", "scene: {sphere: {radius: 1e300}}\n", 1, 26, "too large", ""},
    {"two_kinds", "scene: {sphere: {radius: 1}, box: {size: [1, 1, 1]}}\n", 1, 30, "has 'sphere' and 'box'", "union"},
    {"no_kind", "scene: {translate: [0, 0, 1]}\n", 1, 8, "modifiers but no kind", ""},
    {"missing_scene", "camera: {fov: 40}\n", 1, 1, "missing required key 'scene'", ""},
    {"unknown_material", "materials: {bone: {color: [1, 1, 1]}}\nscene: {sphere: {radius: 1}, material: boen}\n", 2, 40,
     "unknown material 'boen'", "did you mean 'bone'?"},
    {"no_materials", "scene: {sphere: {radius: 1}, material: gold}\n", 1, 40, "unknown material 'gold'", "defines no materials"},
    {"empty_union", "scene: {union: []}\n", 1, 16, "union: the list is empty", ""},
    {"union_not_list", "scene: {union: {sphere: {radius: 1}}}\n", 1, 16, "expected a list of geometry nodes", ""},
    {"camera_at_target", "camera: {position: [1, 1, 1], target: [1, 1, 1]}\nscene: {sphere: {radius: 1}}\n", 1, 9,
     "target is at the camera position", ""},
    {"up_parallel", "camera: {position: [0, 0, 5], target: [0, 0, 0], up: [0, 0, 1]}\nscene: {sphere: {radius: 1}}\n", 1, 54,
     "up is parallel to the view direction", ""},
    {"zero_axis", "scene: {sphere: {radius: 1}, rotate: {axis: [0, 0, 0], degrees: 10}}\n", 1, 45, "must not have zero length", ""},
    {"zero_light_direction", "lights:\n  - directional: {direction: [0, 0, 0]}\nscene: {sphere: {radius: 1}}\n", 2, 30,
     "must not have zero length", ""},
    {"unknown_light", "lights:\n  - spot: {position: [0, 0, 1]}\nscene: {sphere: {radius: 1}}\n", 2, 5, "unknown light kind 'spot'", ""},
    {"point_without_position", "lights:\n  - point: {intensity: 2}\nscene: {sphere: {radius: 1}}\n", 2, 12,
     "missing required key 'position'", ""},
    {"width_zero", "render: {width: 0}\nscene: {sphere: {radius: 1}}\n", 1, 17, "expected a whole number from 1 to 16384", ""},
    {"width_huge", "render: {width: 20000}\nscene: {sphere: {radius: 1}}\n", 1, 17, "from 1 to 16384, got 20000", ""},
    {"width_fraction", "render: {width: 12.5}\nscene: {sphere: {radius: 1}}\n", 1, 17, "expected a whole number", ""},
    {"bad_precision", "render: {precision: dubble}\nscene: {sphere: {radius: 1}}\n", 1, 21, "expected one of float, double",
     "did you mean 'double'?"},
    {"too_many_iterations", "scene: {mandelbulb: {iterations: 5000}}\n", 1, 34, "from 1 to 1000", ""},
    {"de_method_missing", "scene: {mandelbulb: {de: jacobian}}\n", 1, 26,
     "'jacobian' is not a distance-estimation method of mandelbulb; it has: analytic, gradient, potential, sinh", ""},
    {"de_method_typo", "scene: {mandelbox: {de: jacobain}}\n", 1, 25, "it has: analytic, jacobian", "did you mean 'jacobian'?"},
    {"mandelbox_contracting", "scene: {mandelbox: {scale: 0.5}}\n", 1, 28, "expected |scale| > 1", ""},
    {"mandelbox_radii", "scene: {mandelbox: {min_radius: 1.5}}\n", 1, 33, "min_radius (1.5) must be less than fixed_radius", ""},
    {"julia_degree", "scene: {julia: {degree: 4}}\n", 1, 25, "from 2 to 3, got 4", ""},
    {"kifs_symmetry", "scene: {kifs: {symmetry: cubic}}\n", 1, 26, "expected one of tetrahedral", ""},
    {"hybrid_unknown_step", "scene: {hybrid: {steps: [{mandelbub: {}}]}}\n", 1, 27, "unknown formula 'mandelbub'",
     "did you mean 'mandelbulb'?"},
    {"step_factor_zero", "scene: {menger: {}, step_factor: 0}\n", 1, 34, "expected a positive number up to 2", ""},
    {"trap_palette_short", "materials: {m: {orbit_trap: {palette: [[1, 0, 0]]}}}\nscene: {mandelbulb: {}}\n", 1, 39,
     "expected a list of 2 to 16 colours", ""},
    {"trap_unknown_key", "materials: {m: {orbit_trap: {palete: []}}}\nscene: {mandelbulb: {}}\n", 1, 30, "palete", "did you mean 'palette'?"},
    {"box_radius_too_big", "scene: {box: {size: [1, 1, 1], radius: 0.6}}\n", 1, 40, "more than half the smallest side", ""},
    {"smooth_without_children", "scene: {smooth_union: {radius: 0.1}}\n", 1, 23, "missing required key 'children'", ""},
    {"light_list_not_map", "lights: {directional: {}}\nscene: {sphere: {radius: 1}}\n", 1, 9, "expected a list of lights", ""},
    {"scene_is_scalar", "scene: 42\n", 1, 8, "expected a geometry node", ""},
    {"document_is_list", "- sphere: {radius: 1}\n", 1, 1, "a scene file is a map of sections", ""},
    {"yaml_unclosed", "scene: {sphere: {radius: 1}\n", 2, 1, "YAML syntax error", ""},
    {"yaml_tab", "scene:\n\tsphere: {radius: 1}\n", 2, 1, "a tab in the indentation", "use spaces"},
    {"duplicate_key", "scene: {sphere: {radius: 1, radius: 2}}\n", 1, 29, "duplicate key 'radius'", ""},
    {"empty", "", 1, 1, "the scene file is empty", ""},
    {"binary", "scene: \x01\x02\x03\n", 1, 8, "not a text file", ""},
};

class SceneErrors : public ::testing::TestWithParam<Case> {};

TEST_P(SceneErrors, ReportsMessageAndLocation) {
  const Case& c = GetParam();
  std::vector<Diagnostic> diags;
  try {
    diags = errors_of(c.scene);
  } catch (const SceneError& e) {  // errors thrown by the YAML loader itself
    diags = e.diagnostics();
  }
  ASSERT_FALSE(diags.empty()) << "scene was accepted:\n" << c.scene;
  const Diagnostic& d = diags.front();
  EXPECT_NE(d.message.find(c.message), std::string::npos) << "got: " << d.str();
  EXPECT_NE(d.hint.find(c.hint), std::string::npos) << "got hint: " << d.hint;
  EXPECT_EQ(d.loc.line, c.line) << d.str();
  EXPECT_EQ(d.loc.column, c.column) << d.str();
  EXPECT_EQ(d.loc.file ? *d.loc.file : "", "t.yaml");
}

INSTANTIATE_TEST_SUITE_P(AllClasses, SceneErrors, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

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
