// Mandelbulber's formulas that sdfc has as presets with the same map: the
// writer moves the [fractal_N] values onto the preset's parameters and
// refuses the options the preset leaves out (each off by default). The
// bulb and Menger variants here; the Mandelbox variants, the pseudo-Kleinian
// and box_fold_bulb_pow2 in formula_presets_box.cpp.
#include <fmt/format.h>

#include <cmath>

#include "formula_writers.hpp"

namespace sdfc::fract {

void require_off(const FormulaInput& in, const std::string& key) {
  if (in.fractal.boolean(key)) unsupported_setting(in, key, "true");
}

void require_zero(const FormulaInput& in, const std::string& key) {
  if (double v = in.fractal.number(key); v != 0) unsupported_setting(in, key, num(v));
}

Node preset_node(const FormulaInput& in, const char* preset, std::vector<Field> fields, int cap, bool julia) {
  Node n{preset, fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), std::move(fields), {}, {}};
  n.fields.push_back(iterations_field(in, cap));
  n.fields.push_back({"bailout", num(in.bailout), "bailout"});
  if (julia && in.julia) n.fields.push_back({"julia", vec(julia_constant(in)), "julia_mode true, julia_c"});
  return n;
}

void single_rotation(const FormulaInput& in, const std::string& key, const Vec3 (&axes)[3], std::vector<Field>& fields) {
  Vec3 r = in.fractal.vec3(key);
  int turns = (r[0] != 0) + (r[1] != 0) + (r[2] != 0);
  if (turns == 0) return;
  if (turns > 1) unsupported_setting(in, key, vec(r) + " (a turn about one axis maps)");
  size_t i = r[0] != 0 ? 0 : r[1] != 0 ? 1 : 2;
  if (std::fabs(r[i]) > 360) unsupported_setting(in, key, vec(r));
  fields.push_back({"rotation_axis", vec(axes[i]), from(in, key)});
  fields.push_back({"rotation_angle", num(r[i]), from(in, key)});
}

namespace {

// A value inside the preset's range, or refused.
double within(const FormulaInput& in, const std::string& key, double lo, double hi) {
  double v = in.fractal.number(key);
  if (!(v >= lo && v <= hi)) unsupported_setting(in, key, num(v));
  return v;
}

// The Menger formulas add no c unless asked (dont_add_c_constant_N on).
void require_no_c(const FormulaInput& in) {
  if (adds_c(in, false)) unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true (c added)");
}

}  // namespace

// xenodreambuie.cl: sdfc's bulb (acos from the pole, atan2) with the polar
// angle folded into the upper half, then + c.
Node xenodreambuie(const FormulaInput& in) {
  require_c_added(in);
  require_zero(in, "alpha_angle_offset");
  require_zero(in, "beta_angle_offset");
  double power = in.fractal.number("power");
  if (!(power > 1 && power <= 64)) unsupported_setting(in, "power", num(power));
  return preset_node(in, "xenodreambuie", {{"power", num(power), from(in, "power")}}, 60);
}

// menger_mod1.cl: sort |z|, scale, shift x and y by 2·multiplier, z by
// 2·multiplier.z above 1, add transf_addition_constant; no c, as
// Mandelbulber adds none to its Menger formulas unless asked.
Node menger_mod1(const FormulaInput& in) {
  require_no_c(in);
  require_off(in, "transf_rotation_enabled");
  require_off(in, "transf_function_enabledx_false");  // the box offset
  require_off(in, "transf_function_enabled_false");   // the iteration weight
  double scale = in.fractal.number("transf_scale_3");
  if (!(std::fabs(scale) <= 100)) unsupported_setting(in, "transf_scale_3", num(scale));  // the preset's range
  return preset_node(in, "menger_mod1",
                     {{"scale", num(scale), from(in, "transf_scale_3")},
                      {"multiplier", vec(in.fractal.vec3("transf_constant_multiplier_111")),
                       from(in, "transf_constant_multiplier_111")},
                      {"offset", vec(in.fractal.vec3("transf_addition_constant")), from(in, "transf_addition_constant")}},
                     12);
}

// The 4-D formulas (x + y i + z j + w k, w starting at 0, r = |(z, w)|):
// quaternion.cl's Mandelbrot form, hypercomplex.cl (both + (c, 0), c the
// point or julia_c) and aexion.cl, which makes z and c 4-D on its first
// iteration and adds c itself (Mandelbulber adds none on top by default).
Node quaternion_mandelbrot(const FormulaInput& in) {
  require_c_added(in);
  return preset_node(in, "quaternion", {}, 1000);
}

Node hypercomplex(const FormulaInput& in) {
  require_c_added(in);
  return preset_node(in, "hypercomplex", {}, 1000);
}

Node aexion(const FormulaInput& in) {
  if (adds_c(in, false)) unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true (c added twice)");
  Vec3 k = in.main.vec3("fractal_constant_factor");
  if (k != Vec3{1, 1, 1}) unsupported_setting(in, "fractal_constant_factor", vec(k));
  double cadd = in.fractal.number("cadd");
  if (!(std::fabs(cadd) <= 100)) unsupported_setting(in, "cadd", num(cadd));  // the preset's range
  return preset_node(in, "aexion", {{"cadd", num(cadd), from(in, "cadd")}}, 1000);
}

// eiffie_msltoe.cl: the (y, z) angle folded into eight sectors, the power-2
// bulb with y scaled by transf_scale, z pulled along itself by
// transf_offset, scaled by transf_scale_1; + c. Left out: the constant
// added after the power and the c-dependent push (both off by default).
Node eiffie_msltoe(const FormulaInput& in) {
  require_c_added(in);
  if (in.fractal.vec3("transf_addition_constant") != Vec3{0, 0, 0})
    unsupported_setting(in, "transf_addition_constant", vec(in.fractal.vec3("transf_addition_constant")));
  require_off(in, "transf_addCpixel_enabled_false");
  return preset_node(in, "eiffie_msltoe",
                     {{"scale", num(within(in, "transf_scale", -100, 100)), from(in, "transf_scale")},
                      {"offset", num(within(in, "transf_offset", -100, 100)), from(in, "transf_offset")},
                      {"scale1", num(within(in, "transf_scale_1", -100, 100)), from(in, "transf_scale_1")}},
                     60);
}

// menger_cross_kifs.cl, its default part: |y|, |z|, the four plane folds,
// the scale about (sqrt(3)/2, 1.5, 1.5). Left out (off by default): the
// KIFS part before it, abs x, the edge, the x fold and the rotation.
Node menger_cross_kifs(const FormulaInput& in) {
  require_no_c(in);
  if (!in.fractal.boolean("transf_function_enabled")) unsupported_setting(in, "transf_function_enabled", "false");
  for (const char* key : {"transf_function_enabled_false", "transf_function_enabledz_false", "transf_function_enabledx_false",
                          "transf_function_enabledP_false", "transf_function_enabledR_false"})
    require_off(in, key);
  return preset_node(in, "menger_cross_kifs",
                     {{"scale", num(within(in, "transf_scale_3", -100, 100)), from(in, "transf_scale_3")}}, 12);
}

// menger_smooth.cl: the sponge with smooth abs, sort and fold
// (sqrt(t² + transf_offset_0005)), scaled about transf_offset_1105. Left
// out (off by default): the rotation and the iteration weight.
Node menger_smooth(const FormulaInput& in) {
  require_no_c(in);
  require_off(in, "transf_rotation_enabled");
  require_off(in, "transf_function_enabledz_false");
  Vec3 offset = in.fractal.vec3("transf_offset_1105");
  for (double o : offset)
    if (!(std::fabs(o) <= 10)) unsupported_setting(in, "transf_offset_1105", vec(offset));
  return preset_node(in, "menger_smooth",
                     {{"scale", num(within(in, "transf_scale_3", 1.000001, 100)), from(in, "transf_scale_3")},
                      {"offset", vec(offset), from(in, "transf_offset_1105")},
                      {"smooth_offset", num(within(in, "transf_offset_0005", 0, 1)), from(in, "transf_offset_0005")}},
                     12);
}

}  // namespace sdfc::fract
