#pragma once
#include <algorithm>
#include <cmath>

namespace sdfc::ir {
// Radius of a ball that holds the power-n Mandelbulb set: outside it,
// r^n - r > r, so |z| grows every iteration (as 2 bounds the Mandelbrot set).
// Used by the estimator's far-field bound, the bounds pass and the reference.
inline double mandelbulb_set_radius(double power) {
  if (power <= 1.25) return 4.0;
  return std::min(4.0, std::pow(2.0, 1.0 / (power - 1.0)));
}
}  // namespace sdfc::ir
