// More of Mandelbulber's formulas as presets (its formula/definition files,
// parameter names and defaults): Xenodreambuie, Eiffie's Msltoe Julia bulb
// and Knighty's Koch IFS.
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

// Xenodreambuie: the bulb whose polar angle acos(z/r) is folded into
// [0, pi/2] before the power (ph > pi/2 becomes pi - ph), which is the
// polar angle of (x, y, |z|): abs on z, then bulb_power; + c (Mandelbulber
// adds c by default). The angle offsets (alpha, beta) are 0 by default and
// left out.
void xenodreambuie(const PresetArgs& a, ChainBuilder& b) {
  b.add("abs", {0, 0, 1});
  b.add("bulb_power", {a.n("power")});
  b.add("add_c");
}

// Eiffie's Msltoe: the (y, z) angle folded into [0, pi/8] from the y axis
// (eight mirrored sectors), then a power-2 bulb whose m is 1 - z^2/r^2,
// y scaled, then z pulled in by offset along itself, scaled by scale1, + c.
// The fold is polyfold of order 8 on (y, z): the first expr turns (x, y, z)
// into (y, z, x) so the fold sees y and z as its x and y, and the power's
// expr reads them back (x is now z, y is x, z is y). Default off and left
// out: additionConstant000 (0), the c-dependent addCpixel, analyticDE.
void eiffie_msltoe(const PresetArgs& a, ChainBuilder& b) {
  b.expr("y", "z", "x");
  b.add("polyfold", {8});
  // here x = old y, y = old z, z = old x
  const std::string s = fmt::format("({})", a.n("scale"));
  const std::string yx = "(2*z*x*(1 - y*y / (x*x + y*y + z*z))*" + s + ")";
  b.expr("(z*z - x*x) * (1 - y*y / (x*x + y*y + z*z))", yx.c_str(), "2*y*sqrt(z*z + x*x)");
  const double off = a.n("offset"), s1 = a.n("scale1");
  if (off != 0) {
    const std::string k = fmt::format("(1 - ({}) / sqrt(x*x + y*y + z*z))", off);
    b.expr(("x*" + k).c_str(), ("y*" + k).c_str(), ("z*" + k).c_str());
  }
  if (s1 != 1) b.add("scale", {s1});
  b.add("add_c");
}

// Knighty's Koch IFS: abs x, y and sort them (x >= y), y folded at
// scale1/3, then the two swaps "if z > x -+ 1/3" that are reflections in
// the planes z - x = +-1/3, and the scale 3 about offset (1, 0, 0).
// Mandelbulber's own distance |(|z| - |offset|)| / DE is the linear
// estimate r / DE less a constant. The rotation (off by default) is left out.
void koch(const PresetArgs& a, ChainBuilder& b) {
  const double h = 1 / (3 * std::sqrt(2.0));
  b.add("abs", {1, 1, 0});
  b.add("plane_fold", {-1, 1, 0, 0});
  b.add("plane_fold", {0, 1, 0, a.n("scale1") / 3});
  b.add("plane_fold", {-1, 0, 1, h});
  b.add("plane_fold", {-1, 0, 1, -h});
  const auto o = a.v("offset");
  b.add("scale", {a.n("scale"), o[0], o[1], o[2]});
}

}  // namespace

extern const Preset kXenodreambuiePreset{
    "xenodreambuie", "Xenodreambuie's bulb: the polar angle folded to the upper half, then the power, plus c",
    {{"power", 1, {9}, 1.000001, 64, "the power (bulb.power)"}}, 10, 10, xenodreambuie};
extern const Preset kEiffieMsltoePreset{
    "eiffie_msltoe", "Eiffie's Msltoe Julia bulb: the (y, z) angle folded to 8 sectors, a power-2 bulb, plus c",
    {{"scale", 1, {1}, -100, 100, "the scale of the new y (transformCommon.scale)"},
     {"offset", 1, {0}, -100, 100, "z is pulled in by this along itself (transformCommon.offset)"},
     {"scale1", 1, {1}, -100, 100, "the scale after the pull (transformCommon.scale1)"}},
    10, 10, eiffie_msltoe};
extern const Preset kKochPreset{
    "koch", "Knighty's Koch IFS: abs, sort, fold, two swaps with z, scale about (1, 0, 0)",
    {{"scale", 1, {3}, 1.000001, 100, "the scale (transformCommon.scale3)"},
     {"offset", 3, {1, 0, 0}, -100, 100, "the centre of the scale (transformCommon.offset100)"},
     {"scale1", 1, {1}, -100, 100, "three times the y fold (transformCommon.scale1)"}},
    12, 100, koch};

}  // namespace sdfc::formula
