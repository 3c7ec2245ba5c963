// The importer: which sdfc nodes and settings a .fract becomes, what it
// refuses (naming the formula and its id), its warnings, and the commands
// that take a .fract (import, check, render with --set).
#include <gtest/gtest.h>

#include <cmath>

#include "run_sdfc.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/fract/import.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::fract {
namespace {

using test::run_sdfc;
using test::ScratchDir;

std::string fract(const std::string& version, const std::string& main, const std::string& fractal1 = "") {
  return "# Mandelbulber settings file\n# version " + version + "\n# only modified parameters\n[main_parameters]\n" +
         main + "[fractal_1]\n" + fractal1 + "[fractal_2]\n";
}

Imported imported(const std::string& text) { return import_scene(parse_text(text, "t.fract")); }

std::string error_of(const std::string& text) {
  try {
    imported(text);
  } catch (const SceneError& e) {
    const Diagnostic& d = e.diagnostics().at(0);
    return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + " " + d.message;
  }
  return "no error";
}

// The imported YAML builds (the scene sdfc check accepts).
void expect_builds(const Imported& im) {
  ir::Module m = build_module(load_yaml_text(im.yaml, "imported"), "imported");
  EXPECT_NE(m.root, ir::kNoNode);
}

bool has(const std::string& yaml, const std::string& text) { return yaml.find(text) != std::string::npos; }

TEST(FractImport, MandelboxWithItsParametersAndSources) {
  Imported im = imported(fract("2.20", "formula_1 8;\nN 30;\n",
                               "mandelbox_scale -1,5;\nmandelbox_folding_min_radius 0,25;\n"));
  EXPECT_TRUE(has(im.yaml, "  mandelbox:")) << im.yaml;
  EXPECT_TRUE(has(im.yaml, "scale: -1.5")) << im.yaml;
  EXPECT_TRUE(has(im.yaml, "min_radius: 0.25"));
  EXPECT_TRUE(has(im.yaml, "# [fractal_1] mandelbox_folding_min_radius"));
  EXPECT_TRUE(has(im.yaml, "iterations: 30"));
  EXPECT_TRUE(has(im.yaml, "fixed_radius: 1 "));  // Mandelbulber's default
  expect_builds(im);
}

TEST(FractImport, PresetFormulasWithTheirParametersAndSources) {
  Imported x = imported(fract("2.20", "formula_1 11;\nN 9;\n", "power 7;\n"));
  EXPECT_TRUE(has(x.yaml, "  xenodreambuie:")) << x.yaml;
  EXPECT_TRUE(has(x.yaml, "power: 7 ")) << x.yaml;
  EXPECT_TRUE(has(x.yaml, "# [fractal_1] power"));
  EXPECT_TRUE(has(x.yaml, "iterations: 9"));
  expect_builds(x);
  Imported m = imported(fract("2.20", "formula_1 61;\n", "transf_constant_multiplier_111 1 0,85 0,9;\n"));
  EXPECT_TRUE(has(m.yaml, "  menger_mod1:")) << m.yaml;
  EXPECT_TRUE(has(m.yaml, "multiplier: [1, 0.85, 0.9]")) << m.yaml;
  EXPECT_TRUE(has(m.yaml, "scale: 3 "));  // Mandelbulber's default
  EXPECT_TRUE(has(m.yaml, "iterations: 12"));  // N 250, the preset's cap
  expect_builds(m);
}

TEST(FractImport, MengerSpongeAndQuaternionJulia) {
  Imported m = imported(fract("2.20", "formula_1 7;\nN 8;\n"));
  EXPECT_TRUE(has(m.yaml, "  menger:"));
  EXPECT_TRUE(has(m.yaml, "iterations: 8"));
  expect_builds(m);
  Imported q = imported(fract("2.20", "formula_1 5;\njulia_mode true;\njulia_c 0,5 -0,8 -0,78;\n"));
  EXPECT_TRUE(has(q.yaml, "c: [0.5, -0.8, -0.78, 0]")) << q.yaml;
  expect_builds(q);
  // Not in julia mode the quaternion is the 4-D quaternion preset, as are Hypercomplex and Aexion.
  Imported qm = imported(fract("2.20", "formula_1 5;\nN 8;\n"));
  EXPECT_TRUE(has(qm.yaml, "  quaternion:")) << qm.yaml;
  expect_builds(qm);
  Imported h = imported(fract("2.20", "formula_1 4;\nN 8;\n"));
  EXPECT_TRUE(has(h.yaml, "  hypercomplex:")) << h.yaml;
  expect_builds(h);
  Imported a = imported(fract("2.20", "formula_1 19;\nN 8;\n", "cadd 0,25;\n"));
  EXPECT_TRUE(has(a.yaml, "cadd: 0.25")) << a.yaml;
  expect_builds(a);
}

TEST(FractImport, UnsupportedFormulasAreErrorsNamingThemAndTheirIds) {
  EXPECT_EQ(error_of(fract("2.20", "formula_1 6;\n")), "5:11 formula 'minusFastTrig' (id 6) is not supported yet");
  EXPECT_EQ(error_of(fract("2.20", "formula_1 99999;\n")), "5:11 formula id 99999 is not supported yet");
  // A mapped formula with a setting that would change its shape.
  EXPECT_NE(error_of(fract("2.20", "formula_1 8;\n", "mandelbox_folding_value 3;\n"))
                .find("formula 'Mandelbox' (id 8) with mandelbox_folding_value"),
            std::string::npos);
  EXPECT_NE(error_of(fract("2.20", "formula_1 7;\nboolean_operators true;\nfractal_rotation 0 0 10;\n"))
                .find("rotating the fractal in boolean mode"),
            std::string::npos);
  // Mandelbulber's folds before every iteration's formula change any shape.
  EXPECT_EQ(error_of(fract("2.20", "formula_1 7;\nspherical_folding true;\n")),
            "6:19 the general box and spherical folding is not supported yet (spherical_folding = true)");
  EXPECT_NE(error_of(fract("2.20", "box_folding true;\n")).find("(box_folding = true)"), std::string::npos);
  // The presets' writers refuse the options their presets leave out.
  EXPECT_NE(error_of(fract("2.20", "formula_1 11;\n", "alpha_angle_offset 10;\n"))
                .find("formula 'Xenodreambuie' (id 11) with alpha_angle_offset = 10"),
            std::string::npos);
  EXPECT_NE(error_of(fract("2.20", "formula_1 61;\n", "transf_rotation_enabled true;\n"))
                .find("formula 'Menger - Mod 1' (id 61) with transf_rotation_enabled = true"),
            std::string::npos);
  EXPECT_NE(error_of(fract("2.20", "formula_1 7;\nhybrid_fractal_enable true;\nformula_2 1003;\n")).find("formula 'transf_scale' (id 1003)"),
            std::string::npos);
}

TEST(FractImport, CameraFovDetailAndStepFactor) {
  // 2.20: fov is the image height at distance 1: 0.8284 is 45 degrees.
  Imported a = imported(fract("2.20", "formula_1 7;\nfov 0,828427;\ndetail_level 4;\nDE_factor 0,5;\n"));
  EXPECT_TRUE(has(a.yaml, "fov: 44.99")) << a.yaml;
  EXPECT_TRUE(has(a.yaml, "hit_epsilon: 0.25"));
  EXPECT_TRUE(has(a.yaml, "step_factor: 0.5"));
  // From 2.21 on, files hold degrees.
  Imported b = imported(fract("2.21", "formula_1 7;\nfov 45;\n"));
  EXPECT_TRUE(has(b.yaml, "fov: 45 "));
  EXPECT_NE(error_of(fract("2.20", "formula_1 7;\nperspective_type 1;\n")).find("perspective_type 1"), std::string::npos);
}

TEST(FractImport, BooleanModeBecomesCsgPlacedByPositionAndScale) {
  Imported im = imported(fract("2.20",
                               "boolean_operators true;\nformula_1 7;\nformula_2 8;\nboolean_operator_2 2;\n"
                               "formula_position_2 1 0 0;\nformula_scale_2 0,5;\n"));
  EXPECT_TRUE(has(im.yaml, "  difference:")) << im.yaml;
  EXPECT_TRUE(has(im.yaml, "translate: [1, 0, 0]"));
  EXPECT_TRUE(has(im.yaml, "scale: 0.5"));
  expect_builds(im);
}

TEST(FractImport, KeyframesBecomeACameraPathAndOtherColumnsAWarning) {
  Imported im = imported(fract("2.20", "formula_1 7;\n") +
                         "[keyframes]\nframe;main_camera_x;main_camera_y;main_camera_z;fractal0_power\n"
                         "interpolation;morphAkima;morphAkima;morphAkima;morphAkima\n0;3;-3;2;8\n1;3;-4;2;9\n");
  EXPECT_TRUE(has(im.yaml, "keys:")) << im.yaml;
  EXPECT_TRUE(has(im.yaml, "{time: 3.33333"));  // 100 frames per keyframe at 30 frames per second
  ASSERT_EQ(im.warnings.size(), 1u);
  EXPECT_TRUE(has(im.warnings[0], "fractal0_power not imported"));
  expect_builds(im);
}

TEST(FractImport, OneWarningPerUnsupportedGroup) {
  Imported im = imported(fract("2.20", "formula_1 7;\nvolumetric_fog_enabled true;\nvolumetric_fog_density 2;\n"
                                       "aux_light_volumetric_enabled_1 true;\naux_light_volumetric_intensity_1 2;\n"));
  int fog = 0, vol = 0;
  for (const std::string& w : im.warnings) {
    fog += has(w, "volumetric fog");
    vol += has(w, "volumetric light");
  }
  EXPECT_EQ(fog, 1);
  EXPECT_EQ(vol, 1);
}

TEST(FractCommands, ImportCheckAndRenderWithSet) {
  ScratchDir dir;
  std::string src = dir.write("menger.fract", fract("2.20", "formula_1 7;\nN 5;\nimage_width 32;\nimage_height 24;\n"));
  test::RunResult r = run_sdfc("import " + src);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "menger:"));  // stdout without -o
  ASSERT_EQ(run_sdfc("import " + src + " -o " + dir.file("m.yaml")).code, 0);
  EXPECT_EQ(run_sdfc("check " + dir.file("m.yaml")).code, 0);
  EXPECT_TRUE(has(run_sdfc("import --help").out, "Mandelbulber"));
  test::RunResult c = run_sdfc("check " + src + " --set scene.menger.iterations=3");
  EXPECT_EQ(c.code, 0) << c.err;
  // Known by its first line, whatever its name.
  std::string noext = dir.write("scene", fract("2.20", "formula_1 7;\nN 5;\n"));
  EXPECT_EQ(run_sdfc("check " + noext).code, 0);
  test::RunResult bad = run_sdfc("check " + dir.write("bad.fract", fract("2.20", "formula_1 6;\n")));
  EXPECT_EQ(bad.code, 1);
  EXPECT_TRUE(has(bad.err, "bad.fract:5:11: error: formula 'minusFastTrig' (id 6) is not supported yet")) << bad.err;
  // The input is never the output.
  EXPECT_NE(run_sdfc("import " + src + " -o " + src).code, 0);
  EXPECT_TRUE(has(test::read_text(src), "formula_1 7;"));
  test::RunResult img = run_sdfc("render " + src + " -o " + dir.file("m.png") + " --set render.width=16");
  EXPECT_EQ(img.code, 0) << img.err;
}

}  // namespace
}  // namespace sdfc::fract
