// The built-in fractals as presets: the same steps their hand-wired kinds
// run (the kinds `mandelbulb:`, `mandelbox:`, ... keep their own code; the
// presets are the chains a formula can extend).
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

}  // namespace

extern const Preset kMandelbulbPreset{
    "mandelbulb", "White and Nylander's power in spherical coordinates, plus c",
    {{"power", 1, {8}, 1.000001, 64, "the power"}}, 10, 2, mandelbulb, "mandelbulb"};
extern const Preset kMandelboxPreset{
    "mandelbox", "Tom Lowe's box fold, sphere fold and scale, plus c (non-conformal with scale_xyz)",
    {{"scale", 1, {2}, -1e3, 1e3, "the scale per iteration"},
     {"folding_limit", 1, {1}, 1e-6, 100, "the box fold's half size"},
     {"min_radius", 1, {0.5}, 1e-6, 100, "inside it the sphere fold scales up"},
     {"fixed_radius", 1, {1}, 1e-6, 100, "the sphere the fold inverts in"},
     {"scale_xyz", 3, {1, 1, 1}, 0.25, 4, "a scale per axis after the scale: unequal factors make it non-conformal"}},
    12, 100, mandelbox, "mandelbox"};
extern const Preset kMengerPreset{
    "menger_sponge", "the Menger sponge: sort |z|, scale about the corner offset, fold the middle layer back",
    {{"scale", 1, {3}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the corner it scales about"}},
    12, 100, menger, "menger"};
extern const Preset kSierpinskiPreset{
    "sierpinski", "the Sierpinski tetrahedron: tetrahedral folds, scale about the corner offset",
    {{"scale", 1, {2}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the corner it scales about"}},
    16, 100, sierpinski, "sierpinski"};
extern const Preset kKifsPreset{
    "kaleidoscopic_ifs", "Knighty's kaleidoscopic IFS: the cube's folds, a rotation, scale about offset",
    {{"scale", 1, {3}, 1.000001, 1e3, "the shrink per level"},
     {"offset", 3, {1, 1, 1}, -10, 10, "the point it scales about"},
     {"rotation_axis", 3, {0, 0, 1}, -1, 1, "the axis of the rotation after the folds"},
     {"rotation_angle", 1, {0}, -360, 360, "degrees; 0 leaves it out"}},
    12, 100, kifs, "kifs"};

}  // namespace sdfc::formula
