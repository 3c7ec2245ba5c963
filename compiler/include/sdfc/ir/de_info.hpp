#pragma once
// What `sdfc check` says about a fractal node's distance estimator: the
// method and what kind of distance it gives (bound / unknown), and the step
// factor it gets by default: both from the kind's description.
#include <cmath>
#include <string>

#include "sdfc/ir/graph.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::ir {

// The step factor a fractal node gets when its YAML gives none: 1 where the
// estimator never passed a surface in the miss-rate tests, less where it
// measurably overshoots (the example-view and random-ray miss tests, ctest
// -R 'MissRate|DeQuality' -V, print the rates). An explicit `step_factor:`
// on the node replaces it.
//  - mandelbulb/juliabulb analytic: 1. On the example views 0.02 % of rays
//    pass a surface; on random rays with a 100x finer hit epsilon 0.25-0.5 %
//    do, all of them thin interior slivers (log r < 0 inside) that step
//    factors down to 0.7 do not catch either, so a factor would only slow
//    the march.
//  - mandelbox analytic (conformal): |z| / dr overshoots the set's extent
//    by about 1.5 % from outside (0.4 % of the example's rays at 1, none at
//    0.95); 0.9 leaves a margin.
//  - hybrid: 1 (the linear estimator with a large escape radius, see
//    hybrid_escape_radius, passes no surface).
// The non-conformal Mandelbox with the scalar derivative keeps 1: it is
// "unknown" and the overshoot is the point (de: jacobian fixes it).
inline double default_step_factor(const Node& n) {
  const kinds::Description* d = kinds::find(n.kind);
  return d && d->step_factor ? d->step_factor(n) : 1.0;
}

// "analytic, bound in practice" and the like; empty for non-fractals.
inline std::string de_summary(const Node& n) {
  const kinds::Description* d = kinds::find(n.kind);
  return d && d->de_summary ? d->de_summary(n) : "";
}

}  // namespace sdfc::ir
