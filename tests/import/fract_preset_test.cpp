// The formulas the importer writes as sdfc's presets of the same name: each
// [fractal_N] key lands on its preset parameter (with Mandelbulber's
// default where the file leaves it out), the options a preset leaves out
// are refused naming the formula, its id and the key, and the box formulas
// become chain steps inside a hybrid.
#include <gtest/gtest.h>

#include "sdfc/compile.hpp"
#include "fract_text.hpp"
#include "sdfc/fract/import.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::fract {
namespace {

using fract_text::error_of;
using fract_text::fract;
using fract_text::imported;

// The YAML has every line of `want` and builds.
void expect_yaml(const std::string& file, std::initializer_list<const char*> want) {
  Imported im = imported(file);
  for (const char* w : want) EXPECT_NE(im.yaml.find(w), std::string::npos) << w << " in\n" << im.yaml;
  ir::Module m = build_module(load_yaml_text(im.yaml, "imported"), "imported");
  EXPECT_NE(m.root, ir::kNoNode);
}

void expect_refused(const std::string& file, const std::string& message) {
  EXPECT_NE(error_of(file).find(message), std::string::npos) << error_of(file);
}

TEST(FractPresets, BulbAndMengerVariants) {
  expect_yaml(fract("formula_1 70;\nN 9;\n", "transf_scale 1,2;\ntransf_offset 0,1;\n"),
              {"  eiffie_msltoe:", "scale: 1.2 ", "offset: 0.1 ", "scale1: 1 ", "# [fractal_1] transf_offset", "iterations: 9"});
  expect_refused(fract("formula_1 70;\n", "transf_addCpixel_enabled_false true;\n"),
                 "formula 'eiffie_msltoe' (id 70) with transf_addCpixel_enabled_false = true");
  expect_refused(fract("formula_1 70;\n", "transf_addition_constant 0 0,1 0;\n"),
                 "formula 'eiffie_msltoe' (id 70) with transf_addition_constant = [0, 0.1, 0]");

  expect_yaml(fract("formula_1 113;\n", "transf_offset_0005 0,02;\n"),
              {"  menger_smooth:", "scale: 3 ", "offset: [1, 1, 0.5]", "smooth_offset: 0.02", "iterations: 12"});
  expect_refused(fract("formula_1 113;\n", "transf_rotation_enabled true;\n"),
                 "formula 'Menger - Smooth' (id 113) with transf_rotation_enabled = true");
  expect_refused(fract("formula_1 113;\ndont_add_c_constant_1 true;\n"),
                 "formula 'Menger - Smooth' (id 113) with dont_add_c_constant_1");

  expect_yaml(fract("formula_1 98;\n", "transf_scale_3 2,8;\n"), {"  menger_cross_kifs:", "scale: 2.8 "});
  expect_refused(fract("formula_1 98;\n", "transf_function_enabled_false true;\n"),
                 "formula 'Menger - Cross KIFS' (id 98) with transf_function_enabled_false = true");
  expect_refused(fract("formula_1 98;\n", "transf_function_enabled false;\n"),
                 "formula 'Menger - Cross KIFS' (id 98) with transf_function_enabled = false");
}

TEST(FractPresets, BoxVariantsKleinianAndBoxFoldBulb) {
  expect_yaml(fract("formula_1 119;\n", "transf_minR2_p25 0,2;\ntransf_rotation_enabled true;\ntransf_rotation 0 0 20;\n"),
              {"  abox_mod11:", "scale: 2 ", "fold: [1, 1, 1]", "fold_z: 1 ", "min_r2: 0.2 ", "max_r2: 1 ",
               "rotation_axis: [0, 0, 1]", "rotation_angle: 20 ", "scale_g: 1 ", "bailout: 100 "});
  expect_refused(fract("formula_1 119;\n", "transf_rotation_enabled true;\ntransf_rotation 10 0 20;\n"),
                 "formula 'Abox - Mod 11' (id 119) with transf_rotation = [10, 0, 20] (a turn about one axis maps)");
  expect_refused(fract("formula_1 119;\n", "transf_function_enabled_false true;\n"),
                 "formula 'Abox - Mod 11' (id 119) with transf_function_enabled_false = true");
  expect_refused(fract("formula_1 119;\n", "mandelbox_offset 0 0 0,7;\n"),
                 "formula 'Abox - Mod 11' (id 119) with mandelbox_offset = [0, 0, 0.7]");

  expect_yaml(fract("formula_1 132;\n", "transf_addition_constant 0,1 0 0;\ntransf_function_enabledAx_false true;\n"),
              {"  amazing_surf_mod2:", "fold_z: 1 ", "offset: [0.1, 0, 0]", "min_r2: 0.25 "});
  expect_refused(fract("formula_1 132;\n", "aSurf3Folds_order_of_folds_1 type3;\n"),
                 "formula 'Amazing Surf - Mod 2' (id 132) with aSurf3Folds_order_of_folds_1 = type3");
  expect_refused(fract("formula_1 132;\n", "mandelbox_main_rotation_enabled true;\n"),
                 "formula 'Amazing Surf - Mod 2' (id 132) with mandelbox_main_rotation_enabled = true");
  expect_refused(fract("formula_1 132;\n", "transf_function_enabledAy_false true;\n"),
                 "formula 'Amazing Surf - Mod 2' (id 132) with transf_function_enabledAy_false = true");

  expect_yaml(fract("formula_1 103;\n", "transf_addition_constant_0777 0,8 0,7 0,6;\ntransf_minimum_radius_05 0,6;\n"),
              {"  pseudo_kleinian:", "box_size: [0.8, 0.7, 0.6]", "min_r2: 0.6 ", "de_tweak: 0.05 ", "de_size: 1 "});
  expect_refused(fract("formula_1 103;\n", "transf_sphere_inversion_enabled_false true;\n"),
                 "formula 'pseudoKleinian2' (id 103) with transf_sphere_inversion_enabled_false = true");

  expect_yaml(fract("formula_1 16;\n"),
              {"  box_fold_bulb_pow2:", "fold_factor: 2 ", "z_factor: 5 ", "de: linear", "bailout: 10000 "});
  expect_refused(fract("formula_1 16;\n", "boxfold_bulbpow2_z_factor 0;\n"),
                 "formula 'box_fold_bulb_pow2' (id 16) with boxfold_bulbpow2_z_factor = 0");
}

// fractal_rotation turns the point before the formula: the shape turns back,
// by Mᵀ of SetRotation2's Rz·Ry·Rx as one axis and angle.
TEST(FractPresets, FractalRotationTurnsTheShapeBack) {
  expect_yaml(fract("formula_1 7;\nfractal_rotation 0 36 0;\n"), {"rotate: {axis: [0, -1, 0], degrees: 36}"});
  expect_yaml(fract("formula_1 7;\nfractal_rotation 90 90 0;\n"), {"rotate: {axis: [-0.57735", "degrees: 120"});
  expect_refused(fract("formula_1 7;\nlimits_enabled true;\nfractal_rotation 0 0 10;\n"),
                 "rotating the fractal with limits_enabled");
}

// In a hybrid the box formulas are chain steps: the same folds as their presets.
TEST(FractPresets, BoxVariantsAsHybridSteps) {
  const std::string hybrid = "hybrid_fractal_enable true;\nformula_2 8;\nN 12;\n";
  expect_yaml(fract("formula_1 16;\n" + hybrid),
              {"{box_fold: {limit: 2}}, {sphere_fold: {min_radius: 0.5, fixed_radius: 1}}, {scale: 2}, {expr:",
               "{scale_xyz: {scale: [1, 1, 5]}}, add_c, {box_fold: {limit: 1}}"});
  expect_yaml(fract("formula_1 119;\n" + hybrid, "transf_scaleG_1 0,9;\n"),
              {"{surf_fold: {limit: [1, 1, 1], axes: [1, 1, 1]}}, {sphere_fold: {min_radius: 0.5, fixed_radius: 1}}, "
               "{scale: 2}, {scale: 0.9}, add_c"});
  expect_yaml(fract("formula_1 132;\n" + hybrid, "transf_addition_constant 0 0 0,1;\n"),
              {"{surf_fold: {limit: [1, 1, 1], axes: [1, 1, 0]}}, {translate: {offset: [0, 0, 0.1]}}, {sphere_fold:"});
  EXPECT_NE(error_of(fract("formula_1 103;\n" + hybrid)).find("formula 'pseudoKleinian2' (id 103) is not supported yet (in a hybrid)"),
            std::string::npos);
}

}  // namespace
}  // namespace sdfc::fract
