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

// "analytic, bound in practice" and the like; empty for non-fractals.
inline std::string de_summary(const Node& n) {
  if (info(n.kind).category != Category::Fractal) return "";
  int at = de_method_param(n.kind);
  auto method = at < 0 ? DeMethod::Analytic : DeMethod(int(n.params[size_t(at)]));
  std::string what = std::string("de: ") + de_method_name(method);
  bool non_conformal = n.kind == Kind::Mandelbox && (n.params[9] != n.params[10] || n.params[10] != n.params[11]);
  if (non_conformal && method == DeMethod::Analytic)
    return what + ", unknown (non-conformal: the scalar derivative can overshoot; use de: jacobian)";
  if (n.kind == Kind::Hybrid) return what + ", unknown (mixed scalar derivatives overshoot; lower step_factor)";
  if (method == DeMethod::Jacobian) return what + ", near-exact (can overshoot slightly: no conservative term)";
  return what + ", bound in practice (not proven)";
}

}  // namespace sdfc::ir
