#include "functions.hpp"

#include <algorithm>
#include <cmath>

namespace sdfc::expr {

namespace {
double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}
}  // namespace

const std::vector<Function>& functions() {
  static const std::vector<Function> table = {
      {"sin", 1, [](const double* a) { return std::sin(a[0]); }, "sin"},
      {"cos", 1, [](const double* a) { return std::cos(a[0]); }, "cos"},
      {"tan", 1, [](const double* a) { return std::tan(a[0]); }, "tan"},
      {"exp", 1, [](const double* a) { return std::exp(a[0]); }, "exp"},
      {"log", 1, [](const double* a) { return std::log(a[0]); }, "log"},
      {"sqrt", 1, [](const double* a) { return std::sqrt(a[0]); }, "sqrt"},
      {"abs", 1, [](const double* a) { return std::fabs(a[0]); }, "fabs"},
      {"min", 2, [](const double* a) { return std::min(a[0], a[1]); }, "fmin"},
      {"max", 2, [](const double* a) { return std::max(a[0], a[1]); }, "fmax"},
      {"clamp", 3, [](const double* a) { return std::clamp(a[0], std::min(a[1], a[2]), std::max(a[1], a[2])); }, "clamp"},
      {"mix", 3, [](const double* a) { return a[0] + (a[1] - a[0]) * a[2]; }, "mix"},
      {"smoothstep", 3, [](const double* a) { return smoothstep(a[0], a[1], a[2]); }, "smoothstep"},
      // Internal, from derivative(): the sign of u (d|u| = sgn(u) du), and the
      // hull of two values (the derivative of min/max is one of its branches').
      {"sgn", 1, [](const double* a) { return double((a[0] > 0) - (a[0] < 0)); }, "sign", true},
      {"hull", 2, [](const double* a) { return std::fabs(a[0]) > std::fabs(a[1]) ? a[0] : a[1]; }, "fmax", true},
  };
  return table;
}

const Function* find_function(std::string_view name) {
  for (const auto& f : functions())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace sdfc::expr
