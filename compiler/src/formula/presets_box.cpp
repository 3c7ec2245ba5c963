// Mandelbulber's Mandelbox and Amazing Surf variants as presets, with its
// parameter names and defaults (formula/opencl/NAME.cl and the fractal list:
// every one adds c after its code, which the analytic DE's "+ 1" stands for).
// Mandelbulber's r^2 radii become sphere_fold's radii (their square roots).
// Options Mandelbulber ships switched off are left out, as each comment says.
#include <cmath>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

using V = std::array<double, 3>;

void translate(const PresetArgs& a, ChainBuilder& b, const char* name) {
  const auto o = a.v(name);
  if (o != V{0, 0, 0}) b.add("translate", {o[0], o[1], o[2]});
}
void rotate(const PresetArgs& a, ChainBuilder& b) {
  if (a.n("rotation_angle") == 0) return;  // Mandelbulber's default: no turn
  const auto axis = a.v("rotation_axis");
  b.add("rotate", {axis[0], axis[1], axis[2], a.n("rotation_angle")});
}
// The tglad fold on x and y, on z too when fold_z is 1.
void surf_fold(const PresetArgs& a, ChainBuilder& b, double fold_z) {
  const auto f = a.v("fold");
  b.add("surf_fold", {f[0], f[1], f[2], 1, 1, fold_z});
}
void sphere_fold(ChainBuilder& b, double min_r2, double max_r2) {
  b.add("sphere_fold", {std::sqrt(min_r2), std::sqrt(max_r2)});
}

// AboxMod11Iteration: the tglad fold (z too), the sphere fold of r^2 against
// min_r2 and max_r2, the scale, an offset, the rotation, the tweak scale;
// then + c. Left out (off by default): DarkBeam's soft fold, the x/z swap,
// the iteration-curved min_r2 (Cpara), scale vary, the in-formula c with its
// axis orders, the analytic DE tweak, and the sphere fold's centre offset
// (mandelbox offset, 0).
void abox_mod11(const PresetArgs& a, ChainBuilder& b) {
  surf_fold(a, b, a.n("fold_z"));
  sphere_fold(b, a.n("min_r2"), a.n("max_r2"));
  b.add("scale", {a.n("scale")});
  translate(a, b, "offset");
  rotate(a, b);
  if (a.n("scale_g") != 1) b.add("scale", {a.n("scale_g")});
  b.add("add_c");
}

// AmazingSurfMod2Iteration with its default fold (type 1, the tglad fold on
// x and y): an offset, the sphere fold, the scale, the main rotation; + c.
// Left out (off by default): folds 2 and 3 and the other fold types, the soft
// fold, inverted c, the swap, the offset's curved forms, the cylinder fold,
// scale vary, the in-formula c, the sphere fold's centre offset (0).
void amazing_surf_mod2(const PresetArgs& a, ChainBuilder& b) {
  surf_fold(a, b, a.n("fold_z"));
  translate(a, b, "offset");
  sphere_fold(b, a.n("min_r2"), a.n("max_r2"));
  b.add("scale", {a.n("scale")});
  rotate(a, b);
  b.add("add_c");
}

// The chain AmazingSurfMod4 and AboxMod15 share: the fold, an offset, the
// sphere fold, the scale, a second offset, the rotation; + c.
void offset_fold_chain(const PresetArgs& a, ChainBuilder& b, double fold_z, double max_r2) {
  surf_fold(a, b, fold_z);
  translate(a, b, "offset");
  sphere_fold(b, a.n("min_r2"), max_r2);
  b.add("scale", {a.n("scale")});
  translate(a, b, "post_offset");
  rotate(a, b);
  b.add("add_c");
}

// AmazingSurfMod4Iteration: the tglad fold on x and y, an offset, then
// z * scale / clamp(r^2, min_r2, 1) (the sphere fold with fixed radius 1 and
// the scale), a second offset, the rotation; + c. Left out (off by default):
// the sphere inversion, scale vary, the first rotation and the swapped c.
void amazing_surf_mod4(const PresetArgs& a, ChainBuilder& b) { offset_fold_chain(a, b, 0, 1); }

// AboxMod15Iteration (the form with minR2p25 and maxR2d1): the tglad fold
// (z too), an offset, the sphere fold, the scale, a second offset, the
// rotation; + c. Left out (off by default): the abs and axis order before
// the fold, the sphere inversion, the first rotation, the in-formula c, the
// diagonal fold (functionEnabledN) and scale vary.
void abox_mod15(const PresetArgs& a, ChainBuilder& b) { offset_fold_chain(a, b, a.n("fold_z"), a.n("max_r2")); }

const PresetParam kScale{"scale", 1, {2}, -1e3, 1e3, "the scale (mandelbox scale)"};
const PresetParam kFold{"fold", 3, {1, 1, 1}, 1e-6, 100, "the tglad fold's limits (additionConstant111)"};
const PresetParam kFoldZ{"fold_z", 1, {1}, 0, 1, "1 folds z too (functionEnabled)"};
const PresetParam kMinR2{"min_r2", 1, {0.25}, 1e-6, 100, "inside r^2 < min_r2 the sphere fold scales up (minR2p25)"};
const PresetParam kMaxR2{"max_r2", 1, {1}, 1e-6, 100, "the sphere fold inverts in r^2 = max_r2 (maxR2d1)"};
const PresetParam kAxis{"rotation_axis", 3, {0, 0, 1}, -1, 1, "the axis of the rotation"};
const PresetParam kAngle{"rotation_angle", 1, {0}, -360, 360, "degrees; 0 leaves it out"};

}  // namespace

extern const Preset kAboxMod11Preset{
    "abox_mod11", "Mandelbulber's ABox Mod 11: tglad fold, sphere fold, scale, offset, rotation, plus c",
    {kScale, kFold, kFoldZ, kMinR2, kMaxR2,
     {"offset", 3, {0, 0, 0}, -100, 100, "added after the scale (additionConstant000)"}, kAxis, kAngle,
     {"scale_g", 1, {1}, -100, 100, "the tweak scale after the rotation (scaleG1)"}},
    12, 100, abox_mod11};
extern const Preset kAmazingSurfMod2Preset{
    "amazing_surf_mod2", "Mandelbulber's Amazing Surf Mod 2: fold x and y, offset, sphere fold, scale, plus c",
    {kScale, kFold, {"fold_z", 1, {0}, 0, 1, "1 folds z too (functionEnabledAxFalse)"}, kMinR2, kMaxR2,
     {"offset", 3, {0, 0, 0}, -100, 100, "added before the sphere fold (additionConstant000)"}, kAxis, kAngle},
    12, 100, amazing_surf_mod2};
extern const Preset kAmazingSurfMod4Preset{
    "amazing_surf_mod4", "Mandelbulber's Amazing Surf Mod 4: fold x and y, offset, scale / clamp(r^2), offset, plus c",
    {{"scale", 1, {2}, -1e3, 1e3, "the scale (scale2)"}, kFold, kMinR2,
     {"offset", 3, {0, 0, 0}, -100, 100, "added before the sphere fold (offsetA000)"},
     {"post_offset", 3, {0, 0, 0}, -100, 100, "added after the scale (additionConstantA000)"}, kAxis, kAngle},
    12, 100, amazing_surf_mod4};
extern const Preset kAboxMod15Preset{
    "abox_mod15", "Mandelbulber's ABox Mod 15: tglad fold, offset, sphere fold, scale, offset, rotation, plus c",
    {{"scale", 1, {2}, -1e3, 1e3, "the scale (scale2)"}, kFold, kFoldZ, kMinR2, kMaxR2,
     {"offset", 3, {0, 0, 0}, -100, 100, "added before the sphere fold (offsetA000)"},
     {"post_offset", 3, {0, 0, 0}, -100, 100, "added after the scale (additionConstantA000)"}, kAxis, kAngle},
    12, 100, abox_mod15};

}  // namespace sdfc::formula
