// hypercomplex: the square of z as a commutative hypercomplex (bicomplex)
// number x + y i + z j + w k with ij = k (Mandelbulber's formula 4, after
// David Makin): (x² - y² - z² - w², 2xy - 2zw, 2xz - 2yw, 2xw - 2yz).
// Not conformal: its derivative is the multiplication by 2q, which stretches
// some directions by up to √2 · 2|q|. Mandelbulber's scalar 2|q| is an
// estimate that can overshoot, so a chain with it runs the Jacobian.
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

bool never_conformal(const Step&) { return false; }

// Rows new x, y, z, w over x, y, z, w: multiplication by 2q.
constexpr int kSign[16] = {1, -1, -1, -1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1, 1};
constexpr int kComp[16] = {0, 1, 2, 3, 1, 0, 3, 2, 2, 3, 0, 1, 3, 2, 1, 0};

void hypercomplex_emit(const Step&, EmitState& s) {
  static const char* const names[4] = {"z.x", "z.y", "z.z", "zw"};
  s.w.open("{  // hypercomplex square");
  if (s.jacobian) {
    std::array<std::string, 16> m;
    for (size_t k = 0; k < 16; ++k) m[k] = fmt::format("{}2.0f * {}", kSign[k] < 0 ? "-" : "", names[kComp[k]]);
    emit_rows4(s, m);
  } else {
    s.w.line("dr = 2.0f * sqrt(v3_dot(z, z) + zw * zw) * dr;  // Mandelbulber's estimate");
  }
  s.w.line("const real x = z.x, y = z.y, t = z.z;");
  s.w.line("z = v3(x * x - y * y - t * t - zw * zw, 2.0f * (x * y - t * zw), 2.0f * (x * t - y * zw));");
  s.w.line("zw = 2.0f * (x * zw - y * t);");
  s.w.close();
}

// f = 2|q|: the scalar estimate of a `de:` override; grad 2 q / |q|
DualFactor hypercomplex_dual(const Step&, EmitState&) {
  return {{"const real q = fmax(sqrt(v3_dot(z, z) + zw * zw), K(1e-20f));"},
          "(2.0f * q)", "v3_scale(z, 2.0f / q)", "2.0f * zw / q"};
}
void hypercomplex_eval(const Step&, RefState& s) {
  const double q[4] = {s.z[0], s.z[1], s.z[2], s.w};
  {  // the reference always carries the Jacobian
    std::array<double, 16> m;
    for (size_t k = 0; k < 16; ++k) m[k] = 2 * kSign[k] * q[kComp[k]];
    apply_rows4(s, m);
  }
  s.dr *= 2 * std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  s.z = {q[0] * q[0] - q[1] * q[1] - q[2] * q[2] - q[3] * q[3], 2 * (q[0] * q[1] - q[2] * q[3]),
         2 * (q[0] * q[2] - q[1] * q[3])};
  s.w = 2 * (q[0] * q[3] - q[1] * q[2]);
}

}  // namespace

extern const StepDef kHypercomplex{"hypercomplex", {}, never_conformal, true, hypercomplex_emit, hypercomplex_eval,
                                   "the square of x + y i + z j + w k as a commutative hypercomplex number; a 4-D step. "
                                   "Not conformal: the chain runs the Jacobian (the scalar 2|q| is only an estimate)",
                                   true, hypercomplex_dual};

}  // namespace sdfc::formula
