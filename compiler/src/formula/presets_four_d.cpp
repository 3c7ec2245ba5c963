// The presets with a 4-D z: the quaternion Julia set (the built-in `julia:`
// as a chain), Mandelbulber's Quaternion (formula 5), Hypercomplex (4) and
// Aexion (19).
#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

// q -> q^degree + c, c the four numbers; the 3-D view is the slice w = slice.
void julia(const PresetArgs& a, ChainBuilder& b) {
  b.add("quaternion", {a.n("degree")});
  b.add("add_c");
  const auto c = a.v4("c");
  Chain& ch = b.chain();
  ch.julia = true;
  ch.c = {c[0], c[1], c[2]};
  ch.cw = c[3];
  ch.w_start = a.n("slice");
}

// The built-in julia: draws the same set with its own code when its ranges
// hold (c and the slice within +-4, bailout up to 1e3) and de is left to the compiler.
std::optional<KindNode> julia_kind(const PresetArgs& a, const Chain& c) {
  const std::array<double, 4> q{c.c[0], c.c[1], c.c[2], c.cw};
  if (c.de != DeChoice::Auto || !c.julia || !within(c.bailout, 1, 1e3) || c.iterations > 1000 ||
      !within(c.w_start, -4, 4))
    return std::nullopt;
  for (double x : q)
    if (!within(x, -4, 4)) return std::nullopt;
  return KindNode{"julia", {{"c", {q[0], q[1], q[2], q[3]}}, {"degree", {a.n("degree")}},
                            {"iterations", {double(c.iterations)}}, {"slice", {c.w_start}}, {"bailout", {c.bailout}}}};
}

// Mandelbulber's Quaternion: q -> q^2 + c, c the point with w 0.
void quaternion(const PresetArgs&, ChainBuilder& b) {
  b.add("quaternion", {2});
  b.add("add_c");
}

// Mandelbulber's Hypercomplex: the commutative square, + c.
void hypercomplex(const PresetArgs&, ChainBuilder& b) {
  b.add("hypercomplex");
  b.add("add_c");
}

// Mandelbulber's Aexion: quadray on the first iteration (z and c alike),
// then the quadray square plus c's quadray form. Its julia mode takes c's
// x, y, z (a fourth number is not used: c's w is made by quadray).
void aexion(const PresetArgs& a, ChainBuilder& b) {
  b.add("quadray", {a.n("cadd")}).until = 1;
  b.add("aexion", {a.n("cadd")});
}

}  // namespace

extern const Preset kJuliaPreset{
    "julia", "the quaternion Julia set q -> q^degree + c, sliced at w = slice (the built-in julia: as a chain)",
    {{"c", 4, {-0.2, 0.6, 0.2, 0.2}, -4, 4, "the quaternion constant: real part, i, j, k"},
     {"degree", 1, {2}, 2, 3, "the power, 2 or 3"},
     {"slice", 1, {0}, -4, 4, "w (the k part) of the 3-D slice through the 4-D set"}},
    12, 4, julia, "julia", julia_kind};
extern const Preset kQuaternionPreset{"quaternion", "Mandelbulber's Quaternion: q -> q^2 + c, c the point (w 0)", {}, 10,
                                      10, quaternion};
extern const Preset kHypercomplexPreset{
    "hypercomplex", "Mandelbulber's Hypercomplex: the square of a commutative 4-D number, + c", {}, 10, 10, hypercomplex};
extern const Preset kAexionPreset{
    "aexion", "Aexion's quadray set: z and c made 4-D on the tetrahedron's axes, then the quadray square plus c",
    {{"cadd", 1, {-1.3}, -100, 100, "added to every component of z and c when they are made 4-D"}}, 10, 10, aexion};

}  // namespace sdfc::formula
