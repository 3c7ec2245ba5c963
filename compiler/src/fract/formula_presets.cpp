// Mandelbulber's formulas that sdfc has as presets with the same map: the
// writer moves the [fractal_N] values onto the preset's parameters and
// refuses the options the preset leaves out (each off by default).
#include <fmt/format.h>

#include <cmath>

#include "formula_writers.hpp"

namespace sdfc::fract {
namespace {

void require_off(const FormulaInput& in, const std::string& key) {
  if (in.fractal.boolean(key)) unsupported_setting(in, key, "true");
}

void require_zero(const FormulaInput& in, const std::string& key) {
  if (double v = in.fractal.number(key); v != 0) unsupported_setting(in, key, num(v));
}

Node preset_node(const FormulaInput& in, const char* preset, std::vector<Field> fields, int cap) {
  Node n{preset, fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), std::move(fields), {}, {}};
  n.fields.push_back(iterations_field(in, cap));
  n.fields.push_back({"bailout", num(in.bailout), "bailout"});
  if (in.julia) n.fields.push_back({"julia", vec(julia_constant(in)), "julia_mode true, julia_c"});
  return n;
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
  if (adds_c(in, false)) unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true (c added)");
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

}  // namespace sdfc::fract
