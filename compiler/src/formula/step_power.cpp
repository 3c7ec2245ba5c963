// bulb_power: the White-Nylander power in spherical coordinates, any real
// power. Its scalar derivative n r^(n-1) dr is the one the Mandelbulb has
// always used; an integer power takes the built-in's trig-free form
// (stdlib fold_bulb_int). The Jacobian goes through the spherical
// coordinates (stdlib fold_bulb_j, trig for every power).
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

void bulb_emit(const Step& st, EmitState& s) {
  std::string n = s.lit.real(st.a[0]);
  if (s.jacobian) {
    s.used.insert("fold_bulb_j");
    s.w.line(fmt::format("fold_bulb_j(&z, &ja, &jb, &jc, {});  // bulb_power {}", n, st.a[0]));
  } else if (st.a[0] >= 2 && st.a[0] <= 64 && st.a[0] == std::floor(st.a[0])) {
    // an integer power: the built-in Mandelbulb's trig-free form
    s.used.insert("fold_bulb_int");
    s.w.line(fmt::format("{{ real rp; z = fold_bulb_int(z, {0}, &rp); dr = rp * {1} * dr; }}  // bulb_power {0}, trig-free",
                         int(st.a[0]), n));
  } else {
    s.used.insert("fold_bulb");
    s.w.line(fmt::format("z = fold_bulb(z, {}, &dr);  // bulb_power {}", n, st.a[0]));
  }
}

// f = n r^(n-1): grad n (n-1) r^(n-3) z
DualFactor bulb_dual(const Step& st, EmitState& s) {
  const std::string n = s.lit.real(st.a[0]);
  return {{"const real r = fmax(v3_length(z), K(1e-20f));", fmt::format("const real f = {0} * pow(r, {0} - 1.0f);", n)},
          "f",
          fmt::format("v3_scale(z, f * ({} - 1.0f) / (r * r))", n)};
}
void bulb_eval(const Step& st, RefState& s) {
  const double n = st.a[0];
  const V3 z = s.z;
  double r = std::max(std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]), 1e-20);
  double rho2 = std::max(z[0] * z[0] + z[1] * z[1], 1e-30), rho = std::sqrt(rho2);
  double th = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * n, ph = std::atan2(z[1], z[0]) * n;
  double rn = std::pow(r, n), st_ = std::sin(th), ct = std::cos(th), sp = std::sin(ph), cp = std::cos(ph);
  V3 dr{st_ * cp * n * rn / r, st_ * sp * n * rn / r, ct * n * rn / r};
  V3 dth{ct * cp * n * rn, ct * sp * n * rn, -st_ * n * rn};
  V3 dph{-st_ * sp * n * rn, st_ * cp * n * rn, 0};
  for (V3& t : s.j) {
    double a = (z[0] * t[0] + z[1] * t[1] + z[2] * t[2]) / r;
    double b = (z[2] * (z[0] * t[0] + z[1] * t[1]) / rho - rho * t[2]) / (r * r);
    double c = (z[0] * t[1] - z[1] * t[0]) / rho2;
    for (int i = 0; i < 3; ++i) t[i] = dr[i] * a + dth[i] * b + dph[i] * c;
  }
  s.dr = n * std::pow(r, n - 1) * s.dr;
  s.z = {rn * st_ * cp, rn * st_ * sp, rn * ct};
}

}  // namespace

extern const StepDef kBulbPower{"bulb_power", {{"power", 1, {8}, false, 1.000001, 64}}, always_conformal, true, bulb_emit,
                                bulb_eval, "z to the power in spherical coordinates (the Mandelbulb's step)", false, bulb_dual};

}  // namespace sdfc::formula
