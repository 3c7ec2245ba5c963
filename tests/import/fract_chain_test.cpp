// The formulas the importer writes as formula chains: Mandelbulber's own
// Mandelbulb (asin latitude) by its power, Mandelbulb Power 2, the
// Mandelbox's main rotation and constant factor, the Kaleidoscopic IFS and
// hybrids (one period of Mandelbulber's formula sequence per pass).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sdfc/compile.hpp"
#include "fract_text.hpp"
#include "sdfc/fract/import.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::fract {
namespace {

using fract_text::error_of;
using fract_text::fract;
using fract_text::imported;

ir::Module module_of(const std::string& yaml) { return build_module(load_yaml_text(yaml, "imported"), "imported"); }

bool has(const std::string& yaml, const std::string& text) { return yaml.find(text) != std::string::npos; }

// The chain's `iterate:` line.
std::string iterate_of(const std::string& yaml) {
  size_t at = yaml.find("iterate: [");
  return at == std::string::npos ? "" : yaml.substr(at, yaml.find('\n', at) - at);
}

TEST(FractChains, MandelbulbByItsPowerModuloFour) {
  // The new polar angle is p·θ − (p − 1)·π/2: the acos bulb for p = 9 (the default), of −z for p = 7.
  std::string p9 = imported(fract("N 12;\n")).yaml;
  EXPECT_TRUE(has(iterate_of(p9), "[{bulb_power: 9}, add_c]")) << p9;
  std::string p7 = imported(fract("N 12;\n", "power 7;\n")).yaml;
  EXPECT_TRUE(has(iterate_of(p7), "[{scale: -1}, {bulb_power: 7}, add_c]")) << p7;
  // Even powers are written out: angle doublings for the longitude, (ρ + i·z)^p for the latitude.
  std::string p8 = iterate_of(imported(fract("N 12;\n", "power 8;\nalpha_angle_offset 22,5;\n")).yaml);
  EXPECT_TRUE(has(p8, "{rotate: {axis: [0, 0, 1], angle: 22.5}}")) << p8;
  EXPECT_GE(std::count(p8.begin(), p8.end(), '/'), 3);  // three doublings, then the latitude
  EXPECT_TRUE(has(p8, "z^8"));
  for (const char* power : {"2", "4", "6", "8", "3", "9"})
    EXPECT_NE(module_of(imported(fract("N 12;\n", std::string("power ") + power + ";\n")).yaml).root, ir::kNoNode) << power;
  EXPECT_TRUE(has(error_of(fract("", "power 5,5;\n")), "with power = 5.5"));
  EXPECT_TRUE(has(error_of(fract("", "power 10;\n")), "powers 2^a 3^b"));
}

// Two derivations of one map: with beta_angle_offset 40 and power 9 the
// latitude turns by 360 degrees, so the written-out polynomials must give the
// acos bulb's distances (both with the Jacobian estimator).
TEST(FractChains, WrittenOutBulbAgreesWithTheAngleRule) {
  auto scene = [](const std::string& fractal) {
    std::string y = imported(fract("N 8;\n", fractal)).yaml;
    y.replace(y.find("    bailout:"), 0, "    de: jacobian\n");
    return module_of(y);
  };
  for (const char* power : {"9", "3"}) {
    std::string beta = std::string(power) == "9" ? "40" : "120";  // p·beta = 360 degrees
    ir::Module a = scene(std::string("power ") + power + ";\n");
    ir::Module b = scene(std::string("power ") + power + ";\nbeta_angle_offset " + beta + ";\n");
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    for (int i = 0; i < 40; ++i) {
      reference::Vec3 p{u(rng), u(rng), u(rng)};
      double da = reference::distance(a, p), db = reference::distance(b, p);
      EXPECT_NEAR(da, db, 1e-6 * (1 + std::fabs(da))) << "power " << power << " at " << p[0] << " " << p[1] << " " << p[2];
    }
  }
}

TEST(FractChains, MandelbulbPower2AndTheConstantFactor) {
  std::string p2 = iterate_of(imported(fract("formula_1 3;\nN 12;\n")).yaml);
  EXPECT_TRUE(has(p2, "z: \"-2*z*")) << p2;
  // c times fractal_constant_factor: an expr in the Mandelbrot form, the julia constant scaled in julia mode.
  Imported box = imported(fract("formula_1 8;\nN 12;\nfractal_constant_factor 1,5 1,5 1,5;\n"));
  EXPECT_TRUE(has(iterate_of(box.yaml), "{expr: {x: \"x + 1.5*cx\"")) << box.yaml;
  EXPECT_NE(module_of(box.yaml).root, ir::kNoNode);
  Imported julia = imported(fract("formula_1 8;\nN 12;\nfractal_constant_factor 2 2 2;\njulia_mode true;\njulia_c 0,5 0 0;\n"));
  EXPECT_TRUE(has(julia.yaml, "julia: [1, 0, 0]")) << julia.yaml;
}

TEST(FractChains, MandelboxMainRotationAsRotateSteps) {
  // The main rotation is SetRotation2(r): Rz(r.z)·Ry(r.y)·Rx(r.x), z turns about x first.
  std::string it = iterate_of(imported(fract("formula_1 8;\nN 12;\n", "mandelbox_main_rotation_enabled true;\nmandelbox_rotation_main 10 20 30;\n")).yaml);
  EXPECT_TRUE(has(it, "{rotate: {axis: [1, 0, 0], angle: 10}}, {rotate: {axis: [0, 1, 0], angle: 20}}, "
                      "{rotate: {axis: [0, 0, 1], angle: 30}}, {scale: 2}")) << it;
  // Mirrored (legacy coordinates), the turns about x and z reverse.
  std::string mirrored = iterate_of(imported(fract("formula_1 8;\nN 12;\nlegacy_coordinate_system true;\n",
                                                   "mandelbox_main_rotation_enabled true;\nmandelbox_rotation_main 10 20 30;\n")).yaml);
  EXPECT_TRUE(has(mirrored, "angle: -10}}, {rotate: {axis: [0, 1, 0], angle: 20}}, {rotate: {axis: [0, 0, 1], angle: -30}}"))
      << mirrored;
  // The IFS's rotations are SetRotation3(r): Rz(r.x)·Ry(r.y)·Rx(r.z).
  std::string ifs = iterate_of(imported(fract("formula_1 10;\nN 12;\n", "IFS_enabled_0 true;\nIFS_rotations_0 10 20 30;\n")).yaml);
  EXPECT_TRUE(has(ifs, "{rotate: {axis: [1, 0, 0], angle: 30}}, {rotate: {axis: [0, 1, 0], angle: 20}}, "
                       "{rotate: {axis: [0, 0, 1], angle: 10}}, {plane_fold")) << ifs;
}

TEST(FractChains, KaleidoscopicIfsVectorsEdgesAndMengerMode) {
  std::string ifs = "IFS_abs_x true;\nIFS_abs_y true;\nIFS_abs_z true;\nIFS_enabled_0 true;\nIFS_direction_0 0 3 4;\n"
                    "IFS_distance_0 0,5;\nIFS_edge 1 0 0;\nIFS_scale 3;\nIFS_offset 1 1 1;\n";
  Imported im = imported(fract("formula_1 10;\nN 12;\n", ifs));
  std::string it = iterate_of(im.yaml);
  // Reflect where z·d < distance: the plane fold with normal −d/|d| and offset −distance.
  EXPECT_TRUE(has(it, "[{abs: {axes: [1, 1, 1]}}, {plane_fold: {normal: [0, -0.6, -0.8], offset: -0.5}}, "
                      "{plane_fold: {normal: [1, 0, 0], offset: 1}}, {scale: {scale: 3, offset: [1, 1, 1]}}]")) << it;
  EXPECT_NE(module_of(im.yaml).root, ir::kNoNode);
  // Menger mode: z.z −= 2 above 1 is, before the next abs, the fold at 1.
  std::string menger = iterate_of(imported(fract("formula_1 10;\nN 12;\n", ifs + "IFS_menger_sponge_mode true;\n")).yaml);
  EXPECT_TRUE(has(menger, "{scale: {scale: 3, offset: [1, 1, 0]}}, {plane_fold: {normal: [0, 0, 1], offset: 1}}]")) << menger;
  // Mirrored (legacy coordinates), y = |y| becomes y = −|y|: a fold of y > 0.
  std::string mirrored = iterate_of(imported(fract("formula_1 10;\nN 12;\nlegacy_coordinate_system true;\n", ifs)).yaml);
  EXPECT_TRUE(has(mirrored, "[{abs: {axes: [1, 0, 1]}}, {plane_fold: {normal: [0, 1, 0], offset: 0}}, "
                            "{plane_fold: {normal: [0, 0.6, -0.8], offset: -0.5}}")) << mirrored;
  EXPECT_TRUE(has(error_of(fract("formula_1 10;\n", "IFS_menger_sponge_mode true;\nIFS_offset 1 1 1;\n")), "IFS_menger_sponge_mode"));
  EXPECT_TRUE(has(error_of(fract("formula_1 10;\n", "IFS_enabled_0 true;\nIFS_intensity_0 0,5;\n")), "IFS_intensity_0"));
}

TEST(FractChains, IfsRotationIsOnInFilesOf206AndBefore) {
  // Mandelbulber turns IFS_rotation_enabled on in fractals 1 ... 4 when it loads a file of 2.06 or before.
  auto it = [](const char* version) {
    std::string text = fract("formula_1 10;\nN 12;\n", "IFS_enabled_0 true;\nIFS_rotation 30 0 0;\n");
    text.replace(text.find("2.20"), 4, version);
    return iterate_of(imported(text).yaml);
  };
  EXPECT_TRUE(has(it("2.05"), "{rotate: {axis: [0, 0, 1], angle: 30}}")) << it("2.05");
  EXPECT_TRUE(has(it("2.06"), "{rotate: {axis: [0, 0, 1], angle: 30}}")) << it("2.06");
  EXPECT_FALSE(has(it("2.07"), "rotate")) << it("2.07");
}

TEST(FractChains, HybridIsOnePeriodOfTheSequencePerPass) {
  // Mandelbox twice, then the Menger sponge: a period of 3 iterations.
  Imported im = imported(fract("hybrid_fractal_enable true;\nformula_1 8;\nformula_2 7;\nformula_iterations_1 2;\nN 30;\n"));
  std::string it = iterate_of(im.yaml);
  size_t first = it.find("box_fold"), second = it.find("box_fold", first + 1), menger = it.find("menger_fold");
  EXPECT_TRUE(first < second && second < menger && menger != std::string::npos) << it;
  EXPECT_EQ(it.find("box_fold", second + 1), std::string::npos);
  EXPECT_TRUE(has(im.yaml, "iterations: 10 ")) << im.yaml;
  EXPECT_NE(module_of(im.yaml).root, ir::kNoNode);
  // Mirrored (legacy coordinates), y flips back after the Menger fold's abs, before the next c.
  std::string mirrored = iterate_of(imported(fract("hybrid_fractal_enable true;\nformula_1 8;\nformula_2 7;\nN 30;\n"
                                                   "legacy_coordinate_system true;\n")).yaml);
  EXPECT_TRUE(has(mirrored, "offset: [1, 1, 1]}}, {scale_xyz: {scale: [1, -1, 1]}}]")) << mirrored;
  // A formula without a chain form names itself.
  EXPECT_TRUE(has(error_of(fract("hybrid_fractal_enable true;\nformula_1 8;\nformula_2 5;\n")),
                  "formula 'Quaternion' (id 5) is not supported yet (in a hybrid)"));
  // No period (the Menger sponge stops after iteration 3) and too long for one pass.
  EXPECT_TRUE(has(error_of(fract("hybrid_fractal_enable true;\nformula_1 8;\nformula_2 7;\nformula_stop_iteration_2 3;\nN 100;\n")),
                  "sdfc's chain takes 64"));
}

}  // namespace
}  // namespace sdfc::fract
