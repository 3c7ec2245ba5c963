// Mandelbulber's Newton Pow3 (formula "newton_pow3", gannjondal's 3-D Newton
// method for t^3 + c = 0) as its upstream source writes it; Mandelbulber
// 2.20 does not have it. Newton's method converges, so the formula looks at
// t through an inversion about the root `solution`: points whose t runs to
// that root escape, the others (drawn to the other roots) stay bounded, and
// the surface is the edge of the root's basin. Parameter names and defaults
// are Mandelbulber's.
#include "sdfc/formula/preset.hpp"

#include <cmath>

namespace sdfc::formula {
namespace {

using V = std::array<double, 3>;

// The abs of the chosen axes (functionEnabledAx..AzFalse), t = (x, -y, -z)
// scaleA1 / r^2 + solution, the Newton step, z = (x, -y, -z) scaleB1 / |t -
// solution|^2, then offset000 and, only when Mandelbulber's "c pixel
// addition" is ticked (off by default), c. Mandelbulber's estimate
// multiplies DE by 2 r per iteration, a guess; sdfc carries the Newton
// step's Jacobian instead and takes the log estimator.
void newton_pow3(const PresetArgs& a, ChainBuilder& b) {
  const V axes = a.v("abs"), off = a.v("offset"), c = a.v("c");
  const double root = a.n("solution");
  if (axes != V{0, 0, 0}) b.add("abs", {axes[0], axes[1], axes[2]});
  b.add("spherical_invert", {std::sqrt(a.n("pre_scale"))});
  b.add("scale_xyz", {1, -1, -1});
  b.add("translate", {root, 0, 0});
  b.add("triplex_newton", {c[0], c[1], c[2], a.n("scale")});
  b.add("translate", {-root, 0, 0});
  b.add("spherical_invert", {std::sqrt(a.n("post_scale"))});
  b.add("scale_xyz", {1, -1, -1});
  if (off != V{0, 0, 0}) b.add("translate", {off[0], off[1], off[2]});
  if (a.n("add_c") != 0) b.add("add_c");
}

}  // namespace

extern const Preset kNewtonPow3Preset{
    "newton_pow3", "Mandelbulber's Newton Pow3: the basin of one root of t^3 + c = 0 under Newton's method, seen inverted",
    {{"c", 3, {-1, 0, 0}, -100, 100, "the polynomial's constant (scaleNeg1, offsetA0, offsetB0)"},
     {"solution", 1, {1}, -100, 100, "the root whose basin is the outside (offset100's x)"},
     {"scale", 1, {1}, 1e-3, 1e3, "scales the Newton correction's denominator (scale1)"},
     {"pre_scale", 1, {1}, 1e-6, 1e6, "the first inversion's r^2 (scaleA1)"},
     {"post_scale", 1, {1}, 1e-6, 1e6, "the second inversion's r^2 (scaleB1)"},
     {"abs", 3, {0, 0, 0}, 0, 1, "1 takes the absolute value of that axis first (functionEnabledAx..Az)"},
     {"offset", 3, {0, 0, 0}, -100, 100, "added after the step (offset000)"},
     {"add_c", 1, {0}, 0, 1, "1 adds c after each iteration (c pixel addition, off by default)"}},
    12, 10, newton_pow3};

}  // namespace sdfc::formula
