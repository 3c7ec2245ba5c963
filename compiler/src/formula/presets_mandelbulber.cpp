// Mandelbulber's formulas as presets, with its parameter names and defaults
// (the formula files of mandelbulber2/formula/definition/): the steps are
// its FormulaCode line for line where the chain's steps allow.
#include <algorithm>
#include <cmath>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

// White's power-2 bulb as its polynomial: (x^2 - y^2)(1 - z^2/(x^2 + y^2)),
// 2xy (1 - z^2/(x^2 + y^2)), -2z sqrt(x^2 + y^2); then + c.
void bulb_power_2(const PresetArgs&, ChainBuilder& b) {
  b.expr("(x*x - y*y) * (1 - z*z / (x*x + y*y))", "2*x*y * (1 - z*z / (x*x + y*y))", "-2*z*sqrt(x*x + y*y)");
  b.add("add_c");
}

// Theli-at's pseudo-Kleinian (Knighty's version): the box fold of size
// box_size, the inversion in r^2 = min_r2, an offset; its own estimate.
void pseudo_kleinian(const PresetArgs& a, ChainBuilder& b) {
  const auto s = a.v("box_size"), o = a.v("offset");
  b.add("surf_fold", {s[0], s[1], s[2], 1, 1, 1});
  b.add("kleinian_fold", {a.n("min_r2"), a.n("de_tweak")});
  if (o != std::array<double, 3>{0, 0, 0}) b.add("translate", {o[0], o[1], o[2]});
  b.chain().de = DeChoice::Kleinian;
  b.chain().kleinian_size = a.n("de_size");
}

// Kali's Amazing Surf: the fold on x and y only, the sphere fold of
// Mandelbulber's form (r^2 against sqrt(min_r) and 1), the scale, plus c.
void amazing_surf(const PresetArgs& a, ChainBuilder& b) {
  const auto f = a.v("fold");
  b.add("surf_fold", {f[0], f[1], f[2], 1, 1, 0});
  b.add("sphere_fold", {std::pow(a.n("min_r"), 0.25), 1});
  b.add("scale", {a.n("scale")});
  b.add("add_c");
  if (a.n("rotation_angle") != 0) {
    const auto axis = a.v("rotation_axis");
    b.add("rotate", {axis[0], axis[1], axis[2], a.n("rotation_angle")});
  }
}

// Mandelbulber's box_fold_bulb_pow2: a box fold at fold_factor, the sphere
// fold (0.5, 1), a scale of 2, the power-2 polynomial, z.z scaled by
// z_factor (non-conformal unless 1), plus c.
void box_fold_bulb_pow2(const PresetArgs& a, ChainBuilder& b) {
  b.add("box_fold", {a.n("fold_factor")});
  b.add("sphere_fold", {0.5, 1});
  b.add("scale", {2});
  b.expr("(x*x - y*y) * (1 - z*z / (x*x + y*y))", "2*x*y * (1 - z*z / (x*x + y*y))", "-2*z*sqrt(x*x + y*y)");
  if (a.n("z_factor") != 1) b.add("scale_xyz", {1, 1, a.n("z_factor")});
  b.add("add_c");
}

}  // namespace

extern const Preset kBulbPower2Preset{"mandelbulb_power_2", "the power-2 Mandelbulb written as its polynomial (no trig)", {}, 10,
                                      2, bulb_power_2};
extern const Preset kPseudoKleinianPreset{
    "pseudo_kleinian", "Theli-at's pseudo-Kleinian: box fold, inversion in a sphere, offset; never escapes",
    {{"box_size", 3, {0.7, 0.7, 0.7}, 1e-3, 100, "the box fold's half sizes (Mandelbulber's additionConstant0777)"},
     {"min_r2", 1, {0.5}, 1e-6, 100, "inside r^2 < min_r2 the fold inverts (minR05)"},
     {"offset", 3, {0, 0, 0}, -100, 100, "added after the inversion (additionConstant000)"},
     {"de_tweak", 1, {0}, 0, 10, "added to the inversion's factor in the estimate (analyticDE tweak)"},
     {"de_size", 1, {1}, 1e-6, 100, "the cylinder radius of the estimate (analyticDE scale1)"}},
    12, 100, pseudo_kleinian};
extern const Preset kAmazingSurfPreset{
    "amazing_surf", "Kali's Amazing Surf: fold x and y, sphere fold, scale, plus c",
    {{"scale", 1, {2}, -1e3, 1e3, "the scale (mandelbox scale)"},
     {"fold", 3, {1, 1, 1}, 1e-6, 100, "the fold limits on x and y (additionConstant111; z is not folded)"},
     {"min_r", 1, {0.5}, 1e-6, 1, "the inner radius of the sphere fold (minR05)"},
     {"rotation_axis", 3, {0, 0, 1}, -1, 1, "the axis of the rotation at the end"},
     {"rotation_angle", 1, {0}, -360, 360, "degrees; 0 leaves it out"}},
    12, 100, amazing_surf};
extern const Preset kBoxFoldBulbPow2Preset{
    "box_fold_bulb_pow2", "box fold, sphere fold, scale 2, the power-2 Mandelbulb polynomial, z scaled, plus c",
    {{"fold_factor", 1, {1}, 1e-6, 100, "the box fold's half size (foldingIntPow foldFactor)"},
     {"z_factor", 1, {1}, 0.01, 100, "the scale of z after the power (foldingIntPow zFactor)"}},
    10, 100, box_fold_bulb_pow2};

}  // namespace sdfc::formula
