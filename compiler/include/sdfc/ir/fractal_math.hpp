#pragma once
// Facts about the fractal sets shared by the schema, the bounds pass, the
// emitter and the reference evaluator.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace sdfc::ir {
// Radius of a ball that holds the power-n Mandelbulb set: outside it,
// r^n - r > r, so |z| grows every iteration (as 2 bounds the Mandelbrot set).
// Used by the estimator's far-field bound, the bounds pass and the reference.
inline double mandelbulb_set_radius(double power) {
  if (power <= 1.25) return 4.0;
  return std::min(4.0, std::pow(2.0, 1.0 / (power - 1.0)));
}

// Escape radius of the Mandelbulb and Juliabulb estimators (analytic and
// dual): at least the bailout, and large enough that one step takes |z| from
// it to 256 or more. The estimate 0.5 log(r) r / dr only agrees across a
// change of escape iteration when |c| is small beside r^n; with a power-3
// bulb and bailout 2, r^n = 8 and the estimate jumps by about a sixth there,
// a step in the distance field that finite-difference normals turn into
// black streaks. The orbit colour and the iteration count keep the bailout.
inline double bulb_estimator_radius(double power, double bailout) {
  return std::max(bailout, std::min(64.0, std::pow(2.0, 8.0 / std::max(power, 1.0))));
}

// Radius R of a ball that holds the Julia set of z <- z^n + c (n > 1):
// for |z| > R, |z^n + c| >= |z|^n - |c| > |z|, so the orbit escapes. R is the
// root of R^n - R - |c| = 0 above 1, found by bisection.
inline double julia_set_radius(double power, double c_norm) {
  double lo = 1.0, hi = 2.0;
  auto f = [&](double r) { return std::pow(r, power) - r - c_norm; };
  while (f(hi) < 0) hi *= 2;
  for (int i = 0; i < 80; ++i) {
    double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return hi;
}

// Half the side of a cube that holds the Mandelbox with these parameters.
// For a coordinate beyond M, the box fold moves it by at most 2 folding_limit
// and the sphere fold is idle (|z| > fixed radius), so with s the smallest
// per-axis magnitude of the scale it becomes at least s (M - 2 fl) - |c|;
// that exceeds M once M > (2 fl s + |c|) / (s - 1). For c = p (not julia)
// Tglad's 2 fl (s + 1) / (s - 1) holds. The larger of both, padded 5 %.
inline double mandelbox_half_extent(double min_axis_scale, double folding_limit, double c_norm, bool julia) {
  double s = min_axis_scale;
  double box = 2 * folding_limit * (s + 1) / (s - 1);
  if (julia) box = std::max(box, (2 * folding_limit * s + c_norm) / (s - 1));
  return 1.05 * box;
}

// Rodrigues' formula: the row-major rotation by `deg` degrees about the
// unit axis a.
inline std::array<double, 9> axis_rotation(const std::array<double, 3>& a, double deg) {
  double t = deg * std::numbers::pi / 180.0, c = std::cos(t), s = std::sin(t), C = 1 - c;
  double x = a[0], y = a[1], z = a[2];
  return {c + x * x * C,     x * y * C - z * s, x * z * C + y * s,
          y * x * C + z * s, c + y * y * C,     y * z * C - x * s,
          z * x * C - y * s, z * y * C + x * s, c + z * z * C};
}

// Codes stored in the IR's double parameters.
enum class KifsSymmetry { Tetrahedral = 0, Octahedral = 1, Icosahedral = 2, Menger = 3 };
enum class HybridStep { Mandelbulb = 0, Mandelbox = 1 };
inline constexpr int kHybridMaxSteps = 4;
// A hybrid's orbit runs until |z| passes this radius (at least 100), not the
// bailout: a Mandelbox step can carry z past a small bailout and fold it
// back, so an early stop leaves a field with jumps the march steps over,
// and the linear estimator r / dr is a bound only once r is large (it is
// below the log estimator 0.5 log(r) r / dr for r > e^2). With 100 no
// sampled ray passed a surface (the DeQuality test); with the bailout (3)
// and the log estimator half of them did.
inline double hybrid_escape_radius(double bailout) { return std::max(bailout, 100.0); }
// Distance-estimation methods (`de:`), stored as a node's `method` parameter.
enum class DeMethod { Analytic = 0, Jacobian = 1, Gradient = 2, Potential = 3, SinhPotential = 4 };
inline const char* de_method_name(DeMethod m) {
  switch (m) {
    case DeMethod::Analytic: return "analytic";
    case DeMethod::Jacobian: return "jacobian";
    case DeMethod::Gradient: return "gradient";
    case DeMethod::Potential: return "potential";
    case DeMethod::SinhPotential: return "sinh";
  }
  return "analytic";
}
inline constexpr int kHybridStepParams = 6;  // kind, repeat, 4 parameters
}  // namespace sdfc::ir
