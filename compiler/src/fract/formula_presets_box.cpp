// Mandelbulber's Mandelbox variants (ABox Mod 11, Amazing Surf Mod 2), the
// pseudo-Kleinian and box_fold_bulb_pow2 as sdfc's presets of the same
// names; in a hybrid, the same steps as a chain part. Each refuses the
// switches its preset leaves out (all off by default).
#include <fmt/format.h>

#include <cmath>

#include "formula_writers.hpp"

namespace sdfc::fract {
namespace {

std::string v3(const Vec3& v) { return vec(v); }

// The box's shared values: Mandelbulber's r² radii and fold limits.
struct BoxValues {
  double scale, min_r2, max_r2, fold_z;
  Vec3 fold, offset;
};

BoxValues box_values(const FormulaInput& in, const char* fold_z_key) {
  const Params& f = in.fractal;
  require_c_added(in);
  require_off(in, "transf_addCpixel_enabled_false");
  require_off(in, "transf_function_enabledSw_false");  // the axis swap
  require_zero(in, "mandelbox_vary_scale_vary");
  if (f.vec3("mandelbox_offset") != Vec3{0, 0, 0}) unsupported_setting(in, "mandelbox_offset", vec(f.vec3("mandelbox_offset")));
  BoxValues b{f.number("mandelbox_scale"), f.number("transf_minR2_p25"), f.number("transf_maxR2_1"),
              double(f.boolean(fold_z_key)), f.vec3("transf_addition_constant_111"), f.vec3("transf_addition_constant")};
  if (!(std::fabs(b.scale) <= 1000)) unsupported_setting(in, "mandelbox_scale", num(b.scale));
  if (!(b.min_r2 >= 1e-6 && b.min_r2 <= 100)) unsupported_setting(in, "transf_minR2_p25", num(b.min_r2));
  if (!(b.max_r2 >= 1e-6 && b.max_r2 <= 100)) unsupported_setting(in, "transf_maxR2_1", num(b.max_r2));
  for (double l : b.fold)
    if (!(l >= 1e-6 && l <= 100)) unsupported_setting(in, "transf_addition_constant_111", vec(b.fold));
  for (double o : b.offset)
    if (!(std::fabs(o) <= 100)) unsupported_setting(in, "transf_addition_constant", vec(b.offset));
  return b;
}

std::vector<Field> box_fields(const FormulaInput& in, const BoxValues& b, const char* fold_z_key) {
  return {{"scale", num(b.scale), from(in, "mandelbox_scale")},
          {"fold", v3(b.fold), from(in, "transf_addition_constant_111")},
          {"fold_z", num(b.fold_z), from(in, fold_z_key)},
          {"min_r2", num(b.min_r2), from(in, "transf_minR2_p25")},
          {"max_r2", num(b.max_r2), from(in, "transf_maxR2_1")},
          {"offset", v3(b.offset), from(in, "transf_addition_constant")}};
}

std::string surf_fold(const BoxValues& b) {
  return fmt::format("{{surf_fold: {{limit: {}, axes: [1, 1, {}]}}}}, ", v3(b.fold), num(b.fold_z));
}
std::string sphere_fold(const BoxValues& b) {
  return fmt::format("{{sphere_fold: {{min_radius: {}, fixed_radius: {}}}}}, ", num(std::sqrt(b.min_r2)), num(std::sqrt(b.max_r2)));
}
std::string translate(const Vec3& o) { return o == Vec3{0, 0, 0} ? "" : fmt::format("{{translate: {{offset: {}}}}}, ", v3(o)); }

// abox_mod11.cl: the tglad fold (z too when transf_function_enabled), the
// sphere fold, the scale, the offset, the rotation, the tweak scale; + c.
// Left out: the soft fold, the iteration-curved min r² and scale vary.
BoxValues abox_mod11_values(const FormulaInput& in) {
  require_off(in, "transf_function_enabled_false");   // DarkBeam's soft fold
  require_off(in, "transf_function_enabledy_false");  // the curved min r² (Cpara)
  return box_values(in, "transf_function_enabled");
}

// amazing_surf_mod2.cl with its default fold (the first, type 1: the tglad
// fold on x and y; z too with transf_function_enabledAx_false), the
// offset, the sphere fold, the scale; + c. Its main rotation is left out:
// as the preset's rotation it agreed with Mandelbulber's render on only 85 %
// of the silhouette (the Mandelbox's own main rotation maps; this one not).
BoxValues amazing_surf_mod2_values(const FormulaInput& in) {
  if (!in.fractal.boolean("transf_function_enabledAx")) unsupported_setting(in, "transf_function_enabledAx", "false");
  if (!in.fractal.boolean("transf_function_enabledAy")) unsupported_setting(in, "transf_function_enabledAy", "false");
  const auto& given = in.fractal.section().entries;  // an enum: "type2" or its index
  if (auto t = given.find("aSurf3Folds_order_of_folds_1"); t != given.end() && t->second.value != "0" && t->second.value != "type1")
    unsupported_setting(in, "aSurf3Folds_order_of_folds_1", t->second.value);
  for (const char* key : {"transf_function_enabledAy_false", "transf_function_enabledAz_false",  // folds 2 and 3
                          "transf_function_enabledCz_false",                                     // the soft fold
                          "transf_function_enabledCx_false",                                     // inverted c
                          "transf_function_enabledBz_false",                                     // the curved offset
                          "transf_function_enabled_false",                                       // the cylinder fold
                          "transf_function_enabledF_false",                                      // scale vary
                          "mandelbox_main_rotation_enabled"})
    require_off(in, key);
  return box_values(in, "transf_function_enabledAx_false");
}

}  // namespace

Node abox_mod11(const FormulaInput& in) {
  BoxValues b = abox_mod11_values(in);
  std::vector<Field> fields = box_fields(in, b, "transf_function_enabled");
  if (in.fractal.boolean("transf_rotation_enabled")) single_rotation(in, "transf_rotation", kRotation2Axes, fields);
  fields.push_back({"scale_g", num(in.fractal.number("transf_scaleG_1")), from(in, "transf_scaleG_1")});
  return preset_node(in, "abox_mod11", std::move(fields), 60);
}

ChainPart abox_mod11_chain(const FormulaInput& in) {
  BoxValues b = abox_mod11_values(in);
  std::string s = surf_fold(b) + sphere_fold(b) + fmt::format("{{scale: {}}}, ", num(b.scale)) + translate(b.offset);
  if (in.fractal.boolean("transf_rotation_enabled")) s += rotation2_steps(in.fractal.vec3("transf_rotation"));
  if (double g = in.fractal.number("transf_scaleG_1"); g != 1) s += fmt::format("{{scale: {}}}, ", num(g));
  return {s + add_c_step(in, true), "abox_mod11.cl: tglad fold, sphere fold, scale, offset, rotation, scaleG, + c", 60};
}

Node amazing_surf_mod2(const FormulaInput& in) {
  BoxValues b = amazing_surf_mod2_values(in);
  return preset_node(in, "amazing_surf_mod2", box_fields(in, b, "transf_function_enabledAx_false"), 60);
}

ChainPart amazing_surf_mod2_chain(const FormulaInput& in) {
  BoxValues b = amazing_surf_mod2_values(in);
  std::string s = surf_fold(b) + translate(b.offset) + sphere_fold(b) + fmt::format("{{scale: {}}}, ", num(b.scale));
  return {s + add_c_step(in, true), "amazing_surf_mod2.cl: tglad fold, offset, sphere fold, scale, + c", 60};
}

// pseudo_kleinian.cl (Mandelbulber's pseudoKleinian2): the box fold of
// half size transf_addition_constant_0777, the inversion inside r² =
// transf_minimum_radius_05, the offset; its own estimate (analyticDE_*).
// No c. Left out (off by default): the first sphere inversion, the cross
// KIFS fold, the tglad and box folds before it, the rotation.
Node pseudo_kleinian(const FormulaInput& in) {
  if (adds_c(in, false)) unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true (c added)");
  for (const char* key : {"transf_sphere_inversion_enabled_false", "transf_function_enabledP_false",
                          "transf_function_enabledBy_false", "transf_function_enabledBx_false",
                          "transf_function_enabledR_false"})
    require_off(in, key);
  const Params& f = in.fractal;
  Vec3 box = f.vec3("transf_addition_constant_0777"), offset = f.vec3("transf_addition_constant");
  for (double s : box)
    if (!(s >= 1e-3 && s <= 100)) unsupported_setting(in, "transf_addition_constant_0777", vec(box));
  for (double o : offset)
    if (!(std::fabs(o) <= 100)) unsupported_setting(in, "transf_addition_constant", vec(offset));
  if (in.mirror_y) offset[1] = -offset[1];  // the box and the sphere are their own mirror images
  double min_r2 = f.number("transf_minimum_radius_05"), tweak = f.number("analyticDE_tweak_005"),
         size = f.number("analyticDE_scale_1");
  if (!(min_r2 >= 1e-6 && min_r2 <= 100)) unsupported_setting(in, "transf_minimum_radius_05", num(min_r2));
  if (!(tweak >= 0 && tweak <= 10)) unsupported_setting(in, "analyticDE_tweak_005", num(tweak));
  if (!(size >= 1e-6 && size <= 100)) unsupported_setting(in, "analyticDE_scale_1", num(size));
  return preset_node(in, "pseudo_kleinian",
                     {{"box_size", vec(box), from(in, "transf_addition_constant_0777")},
                      {"min_r2", num(min_r2), from(in, "transf_minimum_radius_05")},
                      {"offset", vec(offset), from(in, "transf_addition_constant")},
                      {"de_tweak", num(tweak), from(in, "analyticDE_tweak_005")},
                      {"de_size", num(size), from(in, "analyticDE_scale_1")}},
                     30, false);  // no c: julia mode changes nothing
}

// box_fold_bulb_pow2.cl: the box fold at boxfold_bulbpow2_folding_factor,
// the sphere fold (0.5, 1), the scale 2, the power-2 polynomial, z times
// boxfold_bulbpow2_z_factor; + c.
namespace {
Vec3 fold_and_z(const FormulaInput& in) {
  require_c_added(in);
  double fold = in.fractal.number("boxfold_bulbpow2_folding_factor"), z = in.fractal.number("boxfold_bulbpow2_z_factor");
  if (!(fold >= 1e-6 && fold <= 100)) unsupported_setting(in, "boxfold_bulbpow2_folding_factor", num(fold));
  if (!(z >= 0.01 && z <= 100)) unsupported_setting(in, "boxfold_bulbpow2_z_factor", num(z));
  return {fold, z, 0};
}
}  // namespace

Node box_fold_bulb_pow2(const FormulaInput& in) {
  Vec3 v = fold_and_z(in);
  return preset_node(in, "box_fold_bulb_pow2",
                     {{"fold_factor", num(v[0]), from(in, "boxfold_bulbpow2_folding_factor")},
                      {"z_factor", num(v[1]), from(in, "boxfold_bulbpow2_z_factor")},
                      {"de", "linear", "Mandelbulber's estimate for this formula (the power-2 step is no log growth here)"}},
                     60);
}

ChainPart box_fold_bulb_pow2_chain(const FormulaInput& in) {
  Vec3 v = fold_and_z(in);
  std::string s = fmt::format(
      "{{box_fold: {{limit: {}}}}}, {{sphere_fold: {{min_radius: 0.5, fixed_radius: 1}}}}, {{scale: 2}}, "
      "{{expr: {{x: \"(x*x - y*y) * (1 - z*z / (x*x + y*y))\", y: \"2*x*y * (1 - z*z / (x*x + y*y))\", "
      "z: \"-2*z*sqrt(x*x + y*y)\"}}}}, ",
      num(v[0]));
  if (v[1] != 1) s += fmt::format("{{scale_xyz: {{scale: [1, 1, {}]}}}}, ", num(v[1]));
  return {s + add_c_step(in, true), "box_fold_bulb_pow2.cl: box fold, sphere fold, scale 2, power-2 polynomial, z scaled, + c",
          60};
}

}  // namespace sdfc::fract
