// The built-in fractals as presets: the same steps their hand-wired kinds
// run. Where the kind draws exactly the values given (its ranges hold, no
// setting only a chain has), the preset renders with the kind's own code:
// the same fractal with its tighter bounds and hand-written estimate, as
// fast as the kind. Otherwise it is the chain.
#include <cmath>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

void mandelbulb(const PresetArgs& a, ChainBuilder& b) {
  b.add("bulb_power", {a.n("power")});
  b.add("add_c");
}

void mandelbox(const PresetArgs& a, ChainBuilder& b) {
  b.add("box_fold", {a.n("folding_limit")});
  b.add("sphere_fold", {a.n("min_radius"), a.n("fixed_radius")});
  b.add("scale", {a.n("scale")});
  const auto s = a.v("scale_xyz");
  if (s != std::array<double, 3>{1, 1, 1}) b.add("scale_xyz", {s[0], s[1], s[2]});  // the non-conformal Mandelbox
  b.add("add_c");
}

void menger(const PresetArgs& a, ChainBuilder& b) {
  const auto o = a.v("offset");
  b.add("menger_fold", {a.n("scale"), o[0], o[1], o[2]});
}

void sierpinski(const PresetArgs& a, ChainBuilder& b) {
  const auto o = a.v("offset");
  b.add("tetra_fold");
  b.add("scale", {a.n("scale"), o[0], o[1], o[2]});
}

void kifs(const PresetArgs& a, ChainBuilder& b) {
  const auto o = a.v("offset"), axis = a.v("rotation_axis");
  b.add("octa_fold");
  if (a.n("rotation_angle") != 0) b.add("rotate", {axis[0], axis[1], axis[2], a.n("rotation_angle")});
  b.add("scale", {a.n("scale"), o[0], o[1], o[2]});
}

using Kind = std::optional<KindNode>;
bool all_within(const std::array<double, 3>& v, double lo, double hi) {
  return within(v[0], lo, hi) && within(v[1], lo, hi) && within(v[2], lo, hi);
}
std::vector<double> numbers(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

Kind mandelbulb_kind(const PresetArgs& a, const Chain& c) {
  const double power = a.n("power");
  if (c.de != DeChoice::Auto || c.bailout > 1e3) return std::nullopt;
  KindNode k{"mandelbulb", {{"power", {power}}, {"iterations", {double(c.iterations)}}, {"bailout", {c.bailout}}}};
  if (c.julia) {  // the Juliabulb: z -> z^power + julia
    if (power < 2 || !all_within(c.c, -4, 4)) return std::nullopt;
    k.values.push_back({"julia", numbers(c.c)});
  }
  return k;
}

Kind mandelbox_kind(const PresetArgs& a, const Chain& c) {
  const double scale = a.n("scale"), min_r = a.n("min_radius"), fixed_r = a.n("fixed_radius");
  const auto s = a.v("scale_xyz");
  const bool uniform = s == std::array<double, 3>{1, 1, 1};
  // the kind escapes at |z| = 100, runs up to 200 iterations and needs an expanding scale
  if (c.de != DeChoice::Auto || c.bailout != 100 || c.iterations > 200) return std::nullopt;
  if (std::fabs(scale) <= 1 || std::fabs(scale) > 8 || min_r >= fixed_r) return std::nullopt;
  if (c.julia && !all_within(c.c, -10, 10)) return std::nullopt;
  if (!uniform && std::fabs(scale) * std::min({s[0], s[1], s[2]}) <= 1) return std::nullopt;
  KindNode k{"mandelbox", {{"scale", {scale}}, {"folding_limit", {a.n("folding_limit")}}, {"min_radius", {min_r}},
                           {"fixed_radius", {fixed_r}}, {"iterations", {double(c.iterations)}}}};
  if (c.julia) k.values.push_back({"julia", numbers(c.c)});
  if (!uniform) {  // the non-conformal Mandelbox: the kind's Jacobian estimate, as the chain's
    k.values.push_back({"scale_xyz", numbers(s)});
    k.values.push_back({"de", {}, "jacobian"});
  }
  return k;
}

// The folding kinds never escape and have no c: only the default bailout and
// no julia, the kind's own corner (1, 1, 1).
bool folds_fit(const PresetArgs& a, const Chain& c, int max_iterations) {
  return c.de == DeChoice::Auto && c.bailout == 100 && !c.julia && c.iterations <= max_iterations &&
         a.v("offset") == std::array<double, 3>{1, 1, 1};
}

Kind menger_kind(const PresetArgs& a, const Chain& c) {
  if (!folds_fit(a, c, 12) || !within(a.n("scale"), 2, 4)) return std::nullopt;
  return KindNode{"menger", {{"scale", {a.n("scale")}}, {"iterations", {double(c.iterations)}}}};
}

Kind sierpinski_kind(const PresetArgs& a, const Chain& c) {
  if (!folds_fit(a, c, 30) || !within(a.n("scale"), 1.000001, 4)) return std::nullopt;
  return KindNode{"sierpinski", {{"scale", {a.n("scale")}}, {"iterations", {double(c.iterations)}}}};
}

// The kind rotates after scaling, the chain before: the same only without a rotation.
Kind kifs_kind(const PresetArgs& a, const Chain& c) {
  const auto o = a.v("offset");
  if (c.de != DeChoice::Auto || c.bailout != 100 || c.julia || c.iterations > 40 || a.n("rotation_angle") != 0 ||
      !within(a.n("scale"), 1.000001, 4) || !all_within(o, -10, 10) || std::hypot(o[0], o[1], o[2]) < 1e-6)
    return std::nullopt;
  return KindNode{"kifs", {{"symmetry", {}, "octahedral"}, {"scale", {a.n("scale")}}, {"offset", numbers(o)},
                           {"iterations", {double(c.iterations)}}}};
}

}  // namespace

extern const Preset kMandelbulbPreset{
    "mandelbulb", "White and Nylander's power in spherical coordinates, plus c",
    {{"power", 1, {8}, 1.000001, 64, "the power"}}, 10, 2, mandelbulb, "mandelbulb", mandelbulb_kind};
extern const Preset kMandelboxPreset{
    "mandelbox", "Tom Lowe's box fold, sphere fold and scale, plus c (non-conformal with scale_xyz)",
    {{"scale", 1, {2}, -1e3, 1e3, "the scale per iteration"},
     {"folding_limit", 1, {1}, 1e-6, 100, "the box fold's half size"},
     {"min_radius", 1, {0.5}, 1e-6, 100, "inside it the sphere fold scales up"},
     {"fixed_radius", 1, {1}, 1e-6, 100, "the sphere the fold inverts in"},
     {"scale_xyz", 3, {1, 1, 1}, 0.25, 4, "a scale per axis after the scale: unequal factors make it non-conformal"}},
    12, 100, mandelbox, "mandelbox", mandelbox_kind};
extern const Preset kMengerPreset{
    "menger_sponge", "the Menger sponge: sort |z|, scale about the corner offset, fold the middle layer back",
    {{"scale", 1, {3}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the corner it scales about"}},
    12, 100, menger, "menger", menger_kind};
extern const Preset kSierpinskiPreset{
    "sierpinski", "the Sierpinski tetrahedron: tetrahedral folds, scale about the corner offset",
    {{"scale", 1, {2}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the corner it scales about"}},
    16, 100, sierpinski, "sierpinski", sierpinski_kind};
extern const Preset kKifsPreset{
    "kaleidoscopic_ifs", "Knighty's kaleidoscopic IFS: the cube's folds, a rotation, scale about offset",
    {{"scale", 1, {3}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the point it scales about"},
     {"rotation_axis", 3, {0, 0, 1}, -1, 1, "the axis of the rotation after the folds"},
     {"rotation_angle", 1, {0}, -360, 360, "degrees; 0 leaves it out"}},
    12, 100, kifs, "kifs", kifs_kind};

}  // namespace sdfc::formula
