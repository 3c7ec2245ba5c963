// Jos Leys' Kleinian as Mandelbulber 2.20 writes it (formula "jos_kleinian",
// JosKleinianIteration), with its parameter names and defaults.
#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

// a = height (foldingValue), b = shift (offset), box = box_size (offset111).
// z is wrapped into the cell [-box.x, box.x) x [1 - box.y, 1 - box.y + a box.y)
// x [-box.z, box.z); above the line y = a (0.5 + 0.2 sin(sign(b) pi (x + b/2) / box.x))
// it turns half round (-b/2, a/2, 0); then z -> -z / |z|^2 and (x, y) -> (-b - x, a + y),
// written as the inversion in the unit sphere, (x, -y, -z) and the shift (-b, a, 0).
// Mandelbulber's own estimate min(y', de_cap) / max(dr, de_min_dr), with
// y' = min(y, a - y) when the spheres are on. Off by default and left out:
// the sphere inversion on the first iteration (sphereInversionEnabledFalse).
void jos_kleinian(const PresetArgs& a, ChainBuilder& b) {
  const double h = a.n("height"), shift = a.n("shift");
  const auto box = a.v("box_size");
  b.add("wrap", {2 * box[0], h * box[1], 2 * box[2], -box[0], 1 - box[1], -box[2]});
  b.add("kleinian_flip", {h, shift, box[0]});
  b.add("spherical_invert", {1, 0, 0, 0});
  b.add("scale_xyz", {1, -1, -1});
  b.add("translate", {-shift, h, 0});
  Chain& c = b.chain();
  c.de = DeChoice::JosKleinian;
  c.jos_cap = a.n("de_cap");
  c.jos_min_dr = a.n("de_min_dr");
  c.jos_height = a.n("spheres") != 0 ? h : 0;
}

}  // namespace

extern const Preset kJosKleinianPreset{
    "jos_kleinian", "Jos Leys' Kleinian: z wrapped into a cell, a half turn above a sine line, an inversion; its own estimate",
    {{"height", 1, {2}, 1e-3, 100, "the cell's height a and the inversion's shift up (foldingValue)"},
     {"shift", 1, {0}, -100, 100, "b: the shift of the inversion along -x and the sine line's phase (offset)"},
     {"box_size", 3, {1, 1, 1}, 1e-3, 100, "the cell's half width in x and z, its height factor in y (offset111)"},
     {"spheres", 1, {1}, 0, 1, "1: the estimate folds y to min(y, a - y), which closes the top (spheresEnabled)"},
     {"de_cap", 1, {0.05}, 1e-6, 100, "the estimate's y is capped at this (analyticDE tweak005)"},
     {"de_min_dr", 1, {1}, 1e-6, 100, "the estimate divides by at least this (analyticDE offset1)"}},
    40, 10, jos_kleinian};

}  // namespace sdfc::formula
