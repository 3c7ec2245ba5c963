// Mandelbulber's Generalized Fold Box (formula 37): its polyhedral fold,
// then the Mandelbox's sphere fold and scale, plus c; Mandelbulber's
// estimate is the Mandelbox's (DE |scale| + 1, the linear form). Left out:
// solid (1 by default; elsewhere Mandelbulber's edge and corner folds are
// no longer isometries, see step_polyhedral.cpp), melt (0 by default: a
// layer where nothing folds), the sphere fold's offset and the main
// rotation (off by default).
#include <cmath>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

void generalized_fold_box(const PresetArgs& a, ChainBuilder& b) {
  b.add("polyhedral_fold", {std::floor(a.n("generalized_fold_type"))});
  b.add("sphere_fold", {a.n("folding_min_radius"), a.n("folding_fixed_radius")});
  b.add("scale", {a.n("scale")});
  b.add("add_c");
}

}  // namespace

extern const Preset kGeneralizedFoldBoxPreset{
    "generalized_fold_box",
    "Mandelbulber's Generalized Fold Box: folds into a polyhedron, then the Mandelbox's sphere fold and scale, plus c",
    {{"generalized_fold_type", 1, {0}, 0, 7,
      "the polyhedron, by Mandelbulber's number: 0 tetrahedron, 1 cube, 2 octahedron, 3 dodecahedron, 4 octahedron and "
      "cube, 5 icosahedron, 6 hexagonal prism, 7 pentagonal prism (mandelbox_generalized_fold_type)"},
     {"scale", 1, {2}, -100, 100, "the scale per iteration (mandelbox_scale)"},
     {"folding_min_radius", 1, {0.5}, 1e-6, 100, "inside it the sphere fold scales up (mandelbox_folding_min_radius)"},
     {"folding_fixed_radius", 1, {1}, 1e-6, 100, "the sphere the fold inverts in (mandelbox_folding_fixed_radius)"}},
    12, 100, generalized_fold_box};

}  // namespace sdfc::formula
