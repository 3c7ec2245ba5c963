#pragma once
// Shared pieces of the conformance suite: the evaluator configurations every
// scene is instantiated over, the tolerances, and a comparator that runs the
// probe kernel on a point set and checks it against the CPU reference.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "sdfc_test_support.hpp"

namespace sdfc::conformance {

using test::V3;

// One OpenCL evaluator: SIMD packet width x precision. Double precision is
// selected the way a user would, through the scene (render.precision).
struct EvalConfig {
  int simd_width;
  bool dbl;
  std::string name() const { return "w" + std::to_string(simd_width) + (dbl ? "_double" : "_float"); }
  std::vector<std::string> overrides() const {
    return {std::string("render.precision=") + (dbl ? "double" : "float")};
  }
};
inline void PrintTo(const EvalConfig& c, std::ostream* os) { *os << c.name(); }
const std::vector<EvalConfig>& eval_configs();  // {1, 8, 16, 64} x {float, double}

// How close an OpenCL distance must be to the double reference.
//
// float: the kernel rounds the scene constants to float (relative 6e-8 each)
//   and runs a chain of ~10-30 float operations (transform: 3 mul-adds per
//   coordinate per transform; primitive: abs/sub/max/dot/sqrt), each adding
//   at most half an ulp of the values involved. With coordinates and
//   constants of magnitude M <= ~5 near the shapes, that is at most about
//   30 * 6e-8 * 5 ~ 1e-5 absolute; far points (|d| up to ~50) scale it, hence
//   the relative term. Observed: < 5e-7 near the shapes.
// double: the kernel computes in double but the probe ABI stores floats, so
//   the best it can do is the correctly rounded float of the double result:
//   within half an ulp, 2^-24 |d|. We allow one float ulp (2^-23 |d|) plus a
//   tiny absolute term for results that straddle a rounding boundary. This
//   is ~100x tighter than float, so a double kernel that silently computes
//   in float fails it.
struct Tolerance {
  double abs;
  double rel;
  // Optional looser bound where the reference is negative (inside), for
  // estimators whose interior value is ill-conditioned; < 0: same as outside.
  double inside_abs = -1;
  double inside_rel = 0;
  // Inside beyond `abs` only the sign must agree (a superattracting orbit's
  // Jacobian, Newton's method near a root, is a cancellation there).
  bool inside_sign = false;
  bool sign_only(double ref) const { return inside_sign && ref < -abs; }
  double allowed(double ref) const {
    if (ref < 0 && inside_abs >= 0) return inside_abs + inside_rel * std::fabs(ref);
    return abs + rel * std::fabs(ref);
  }
};
inline Tolerance kernel_tolerance(bool dbl) { return dbl ? Tolerance{1e-10, 0x1p-23} : Tolerance{1e-5, 1e-5}; }

// Runs the probe on `points` (rounded to float first, as the probe sees
// them) and checks, for every point:
//   distance   |d - ref| <= tol
//   d_mat      scene_dist_mat's distance is bit-identical to scene_dist's
//   material   equals the reference's material where `check_material[i]`
//              (all points when the vector is empty)
// Failures are reported with the first few offending points.
struct ProbeCheck {
  std::vector<V3> points;          // float-rounded
  std::vector<double> ref_d;       // reference distance at points
  std::vector<int> ref_mat;        // reference material at points
  test::ProbeResult got;
};
// `time`: the frame time the kernel gets; the reference evaluates the
// module at that time (reference::at_time).
ProbeCheck probe_and_compare(const ir::Module& m, const EvalConfig& cfg, std::vector<V3> points,
                             const Tolerance& tol, const std::vector<char>& check_material = {}, double time = 0);

// Every point with a reference distance <= 0 (inside or on the surface)
// must lie in the root's inferred bounds: the render kernel clips rays to
// them, so a too-small box would cut geometry off.
void expect_inside_bounds(const ir::Module& m, const std::vector<V3>& points);

}  // namespace sdfc::conformance
