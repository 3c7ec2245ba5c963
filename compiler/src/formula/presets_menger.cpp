// Mandelbulber's Menger sponge variants as presets (mandelbulber2/formula/
// opencl/menger_mod1.cl, menger_smooth.cl, menger3.cl, menger_cross_kifs.cl), with its parameter
// names and defaults. Only the default configuration: the switches
// Mandelbulber ships off (internal rotation, box offset, analytic DE tweak,
// iteration weight) are left out, and so are Menger3's two rotations, which
// default to no rotation, and Menger Cross KIFS's first (KIFS) part, which
// is off by default, with its switched-off abs x, edge, x fold and rotation.
#include <array>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

// A number for an expression, bracketed so that a negative one parses.
std::string num(double v) { return fmt::format("({})", v); }

// Menger Mod1 (Mclarekin, from Knighty): abs and sort, z *= scale, x and y
// shifted by 2 multiplier, z shifted by 2 multiplier.z only above 1, then
// the offset added.
void menger_mod1(const PresetArgs& a, ChainBuilder& b) {
  const double k = a.n("scale");
  const auto m = a.v("multiplier"), o = a.v("offset");
  if (m[2] == 1 && k > 1.000001) {
    // menger_fold's middle-layer fold is this one when its shift is 2 and
    // the threshold 1: the fast conformal step.
    b.add("menger_fold", {k, 2 * m[0] / (k - 1), 2 * m[1] / (k - 1), 2 / (k - 1)});
  } else {
    b.add("octa_fold");
    b.add("scale", {k});
    b.add("translate", {-2 * m[0], -2 * m[1], 0});
    // (1 + u/|u|)/2 is 1 above z = 1 and 0 below: Mandelbulber's branch.
    const std::string zz = fmt::format("z - {}*(1 + (z - 1)/(abs(z - 1) + 1e-30))", num(m[2]));
    b.expr(nullptr, nullptr, zz.c_str());
    b.chain().de = DeChoice::Linear;  // still an IFS: the expr is no power
  }
  if (o != std::array<double, 3>{0, 0, 0}) b.add("translate", {o[0], o[1], o[2]});
}

// Menger Smooth: every abs and every swap of the sort made smooth by
// sqrt(t^2 + s), s = smooth_offset; the middle-layer fold of z likewise;
// then the scale about the offset (z about 0).
void menger_smooth(const PresetArgs& a, ChainBuilder& b) {
  const double k = a.n("scale"), sc1 = k - 1, sc2 = sc1 / k;
  const auto c = a.v("offset");
  const std::string s = num(a.n("smooth_offset"));
  const auto root = [&](const char* v) { return fmt::format("sqrt({0}*{0} + {1})", v, s); };
  const std::string ax = root("x"), ay = root("y"), az = root("z");
  b.expr(ax.c_str(), ay.c_str(), az.c_str());
  // One smooth swap: the pair becomes its smooth max and min, (u+v)/2 +- sqrt((u-v)^2 + s)/2.
  const auto swap = [&](const char* u, const char* v, bool first) {
    const std::string r = fmt::format("sqrt(({0} - {1})*({0} - {1}) + {2})", u, v, s);
    const std::string hi = fmt::format("0.5*({} + {}) + 0.5*{}", u, v, r), lo = fmt::format("0.5*({} + {}) - 0.5*{}", u, v, r);
    return std::array<std::string, 2>{first ? hi : lo, first ? lo : hi};
  };
  const auto xy = swap("x", "y", true), xz = swap("x", "z", true), yz = swap("y", "z", true);
  b.expr(xy[0].c_str(), xy[1].c_str(), nullptr);
  b.expr(xz[0].c_str(), nullptr, xz[1].c_str());
  b.expr(nullptr, yz[0].c_str(), yz[1].c_str());
  const std::string q = num(sc2 * c[2]);
  const std::string fz = fmt::format("{0} - sqrt((z - {0})*(z - {0}) + {1})", q, s);
  b.expr(nullptr, nullptr, fz.c_str());
  b.add("scale", {k, c[0], c[1], 0});
  // An IFS: |z| grows linearly (Mandelbulber's linear DE), though sqrt reads as a power.
  b.chain().de = DeChoice::Linear;
}

// Menger3 (Knighty's sponge): abs and sort, z folded about offset.z / 3,
// the scale about the offset.
void menger3(const PresetArgs& a, ChainBuilder& b) {
  const auto o = a.v("offset");
  b.add("octa_fold");
  // |z - o/3| + o/3: the side below o/3 reflected up.
  b.add("plane_fold", {0, 0, -1, -o[2] / 3});
  b.add("scale", {a.n("scale"), o[0], o[1], o[2]});
}

// Menger Cross KIFS, its default part (CrossMengerKIFS): |y|, |z|, the folds
// in three planes through the axis and in y = 0.5, the scale about
// (sqrt(3)/2, 1.5, 1.5), the offset added.
void menger_cross_kifs(const PresetArgs& a, ChainBuilder& b) {
  const double h = std::sqrt(0.75);
  const auto o = a.v("offset");
  b.add("abs", {0, 1, 1});
  b.add("plane_fold", {-h, 0.5, 0, 0});  // where x sqrt(3)/2 - y/2 < 0
  b.add("plane_fold", {0, -1, 0, 0});    // where y < 0
  b.add("plane_fold", {0, 1, -1, 0});    // where z < y
  b.add("plane_fold", {0, -1, 0, -0.5});  // where y < 0.5
  b.add("scale", {a.n("scale"), h, 1.5, 1.5});
  if (o != std::array<double, 3>{0, 0, 0}) b.add("translate", {o[0], o[1], o[2]});
}

}  // namespace

extern const Preset kMengerMod1Preset{
    "menger_mod1", "Mclarekin's Menger Mod1: sort |z|, scale, shift x and y, shift z above 1, plus an offset",
    {{"scale", 1, {3}, -100, 100, "the scale (transformCommon scale3)"},
     {"multiplier", 3, {1, 1, 1}, -10, 10, "half the shifts after the scale (constantMultiplier111)"},
     {"offset", 3, {0, 0, 0}, -10, 10, "added at the end (additionConstant000)"}},
    12, 100, menger_mod1};
extern const Preset kMengerSmoothPreset{
    "menger_smooth", "the Menger sponge with smooth abs, sort and fold: sqrt(t^2 + smooth_offset) for |t|",
    {{"scale", 1, {3}, 1.000001, 100, "the scale (transformCommon scale3)"},
     {"offset", 3, {1, 1, 0.5}, -10, 10, "the corner scaled about; z is the fold's (offset1105)"},
     {"smooth_offset", 1, {0.005}, 0, 1, "the smoothing; 0 is the sharp sponge (offset0005)"}},
    12, 100, menger_smooth};
extern const Preset kMenger3Preset{
    "menger3", "Knighty's Menger sponge of Mandelbulber's Menger3: sort |z|, fold z about offset.z/3, scale about offset",
    {{"scale", 1, {3}, -100, 100, "the scale (transformCommon scale3)"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the corner scaled about (offset111)"}},
    12, 100, menger3};
extern const Preset kMengerCrossKifsPreset{
    "menger_cross_kifs", "Mandelbulber's Menger Cross KIFS: |y|, |z|, four plane folds, scale about (sqrt(3)/2, 1.5, 1.5)",
    {{"scale", 1, {3}, -100, 100, "the scale (transformCommon scale3)"},
     {"offset", 3, {0, 0, 0}, -10, 10, "added at the end (offset000)"}},
    12, 100, menger_cross_kifs};

}  // namespace sdfc::formula
