#pragma once
// What `sdfc check` says about a fractal node's distance estimator: the
// method and what kind of distance it gives (bound / unknown).
#include <cmath>
#include <string>

#include "sdfc/ir/fractal_math.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::ir {

// The `method` parameter's index for the kinds that have one, else -1.
inline int de_method_param(Kind k) {
  if (k == Kind::Mandelbulb) return 3;
  if (k == Kind::Mandelbox) return 12;
  return -1;
}

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
  int at = de_method_param(n.kind);
  auto method = at < 0 ? DeMethod::Analytic : DeMethod(int(n.params[size_t(at)]));
  switch (n.kind) {
    case Kind::Mandelbox: {
      bool non_conformal = n.params[9] != n.params[10] || n.params[10] != n.params[11];
      return method == DeMethod::Analytic && !non_conformal ? 0.9 : 1.0;
    }
    default: return 1.0;
  }
}

// "analytic, bound in practice" and the like; empty for non-fractals.
inline std::string de_summary(const Node& n) {
  if (info(n.kind).category != Category::Fractal) return "";
  if (n.kind == Kind::Formula) return "";  // sdfc check prints the chain's own account
  int at = de_method_param(n.kind);
  auto method = at < 0 ? DeMethod::Analytic : DeMethod(int(n.params[size_t(at)]));
  std::string what = std::string("de: ") + de_method_name(method);
  bool non_conformal = n.kind == Kind::Mandelbox && (n.params[9] != n.params[10] || n.params[10] != n.params[11]);
  if (non_conformal && method == DeMethod::Analytic)
    return what + ", unknown (non-conformal: the scalar derivative can overshoot; use de: jacobian)";
  if (n.kind == Kind::Hybrid) return what + ", bound in practice (linear estimator r / dr at escape radius 100, not proven)";
  if (method == DeMethod::Jacobian) return what + ", near-exact (can overshoot slightly: no conservative term)";
  return what + ", bound in practice (not proven)";
}

}  // namespace sdfc::ir
