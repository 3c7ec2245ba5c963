// Mandelbulber's Amazing IFS (formula "amazing_ifs", AmazingIfsIteration) as
// its current upstream source writes it (formula/opencl/amazing_ifs.cl, the
// 2021 form); Mandelbulber 2.20 does not have it. Parameter names and
// defaults are Mandelbulber's.
#include "sdfc/formula/preset.hpp"

#include <cmath>

namespace sdfc::formula {
namespace {

using V = std::array<double, 3>;

// An offset (offsetA000), the tglad fold on x and y (z too when fold_z is 1;
// additionConstant0555), a second offset (additionConstantA000), then
// z * scale / clamp(r^2, min_r2, 1) as the sphere fold with fixed radius 1
// and the scale, then the rotation (rotationMatrix2). Mandelbulber adds c
// only when its "c pixel addition" is ticked, off by default: add_c. Its
// linear estimate divides r by the product of the scales; with add_c on,
// sdfc's estimate adds 1 per iteration for c as it does for every chain.
// Left out (off by default): the sphere inversion, the abs of the axes, the
// polyfold, the second fold c - |z| (functionEnabledBx..Bz), scale vary and
// the analytic DE offset (0).
void amazing_ifs(const PresetArgs& a, ChainBuilder& b) {
  const V pre = a.v("pre_offset"), off = a.v("offset"), f = a.v("fold");
  if (pre != V{0, 0, 0}) b.add("translate", {pre[0], pre[1], pre[2]});
  b.add("surf_fold", {f[0], f[1], f[2], 1, 1, a.n("fold_z")});
  if (off != V{0, 0, 0}) b.add("translate", {off[0], off[1], off[2]});
  b.add("sphere_fold", {std::sqrt(a.n("min_r2")), 1});
  if (a.n("scale") != 1) b.add("scale", {a.n("scale")});
  if (a.n("rotation_angle") != 0) {
    const V axis = a.v("rotation_axis");
    b.add("rotate", {axis[0], axis[1], axis[2], a.n("rotation_angle")});
  }
  if (a.n("add_c") != 0) b.add("add_c");
}

}  // namespace

extern const Preset kAmazingIfsPreset{
    "amazing_ifs", "Mandelbulber's Amazing IFS: fold x and y, offset, scale / clamp(r^2, min_r2, 1), rotation; c optional",
    {{"scale", 1, {1}, -1e3, 1e3, "the scale (scale1)"},
     {"fold", 3, {0.5, 0.5, 0.5}, 1e-6, 100, "the tglad fold's limits (additionConstant0555)"},
     {"fold_z", 1, {0}, 0, 1, "1 folds z too (functionEnabledCzFalse)"},
     {"min_r2", 1, {0.25}, 1e-6, 1, "inside r^2 < min_r2 the sphere fold scales up (minR2p25)"},
     {"pre_offset", 3, {0, 0, 0}, -100, 100, "added before the fold (offsetA000)"},
     {"offset", 3, {0, 0, 0}, -100, 100, "added after the fold, before the sphere fold (additionConstantA000)"},
     {"rotation_axis", 3, {0, 0, 1}, -1, 1, "the axis of the rotation"},
     {"rotation_angle", 1, {0}, -360, 360, "degrees; 0 leaves it out (rotation2)"},
     {"add_c", 1, {0}, 0, 1, "1 adds c after each iteration (c pixel addition, off by default)"}},
    12, 100, amazing_ifs};

}  // namespace sdfc::formula
