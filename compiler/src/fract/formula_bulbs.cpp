// Mandelbulber's Mandelbulb (id 2) and Mandelbulb Power 2 (id 3) as formula
// chains. Its Mandelbulb takes the latitude with asin where sdfc's
// bulb_power takes the polar angle with acos: with p the power, its new
// polar angle is p·θ − (p − 1)·π/2, so
//   p ≡ 1 (mod 4): the same map as bulb_power p;
//   p ≡ 3 (mod 4): bulb_power p of −z (the map is odd for odd p);
//   p even (or a beta offset): no rigid change of coordinates gives it, so
//     it is written out: r^p (cos p·lat, sin p·lat) = (ρ + i·z)^p with
//     ρ = |(x, y)|, a polynomial in ρ² and z (odd powers of ρ as one sqrt),
//     and the longitude's power as angle doublings / triplings of (x, y)
//     that keep ρ.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

#include "formula_writers.hpp"

namespace sdfc::fract {
namespace {

// Guarded |(x, y)|² and |(x, y)|: defined (and differentiable) on the z axis.
constexpr const char* kRho2 = "(x*x + y*y + 1e-30)";
constexpr const char* kRho = "sqrt(x*x + y*y + 1e-30)";

double binomial(int n, int k) {
  double b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}

// Re or Im of (ρ + i·z)^p: sum of sign·C(p, j)·ρ^(p−j)·z^j, written out
// with ρ^2 = x*x + y*y.
std::string polynomial(int p, bool imaginary) {
  std::string s;
  for (int j = imaginary ? 1 : 0; j <= p; j += 2) {
    double c = binomial(p, j) * ((j / 2) % 2 ? -1 : 1);
    int a = (p - j) / 2;
    std::string t = num(std::fabs(c));
    if (a > 0) t += a == 1 ? "*(x*x + y*y)" : fmt::format("*(x*x + y*y)^{}", a);
    if ((p - j) % 2) t += std::string("*") + kRho;
    if (j > 0) t += j == 1 ? "*z" : fmt::format("*z^{}", j);
    s += s.empty() ? (c < 0 ? "-" + t : t) : (c < 0 ? " - " : " + ") + t;
  }
  return s;
}

// One step multiplying the longitude of (x, y) by k (2 or 3), keeping ρ.
std::string longitude_step(int k) {
  if (k == 2) return fmt::format("{{expr: {{x: \"(x*x - y*y) / {0}\", y: \"2*x*y / {0}\"}}}}", kRho);
  return fmt::format("{{expr: {{x: \"(x*x*x - 3*x*y*y) / {0}\", y: \"(3*x*x*y - y*y*y) / {0}\"}}}}", kRho2);
}

// The latitude step: (ρ, z) -> (ρ + i·z)^p·e^(i·p·β) in the meridian plane.
std::string latitude_step(int p, double beta_degrees) {
  std::string re = polynomial(p, false), im = polynomial(p, true);
  if (beta_degrees != 0) {
    double t = p * beta_degrees * std::numbers::pi / 180;
    auto clean = [](double v) { return std::fabs(v) < 1e-12 ? 0.0 : v; };  // cos 180° is -1, not -1 ± 1e-16
    std::string c = "(" + num(clean(std::cos(t))) + ")", s = "(" + num(clean(std::sin(t))) + ")";
    std::tie(re, im) = std::pair(fmt::format("{0}*({2}) - {1}*({3})", c, s, re, im), fmt::format("{1}*({2}) + {0}*({3})", c, s, re, im));
  }
  return fmt::format("{{expr: {{x: \"x*({0}) / {1}\", y: \"y*({0}) / {1}\", z: \"{2}\"}}}}", re, kRho, im);
}

}  // namespace

ChainPart mandelbulb_chain(const FormulaInput& in) {
  const Params& f = in.fractal;
  double power = f.number("power");
  int p = int(std::lround(power));
  if (power != p || p < 2 || p > 16) unsupported_setting(in, "power", num(power) + " (whole powers 2 to 16 map)");
  // The alpha offset turns the longitude before the power: a rotation about z
  // (mirrored with the scene); the beta offset turns the latitude.
  double alpha = f.number("alpha_angle_offset") * (in.mirror_y ? -1 : 1), beta = f.number("beta_angle_offset");
  std::string turn = alpha != 0 ? fmt::format("{{rotate: {{axis: [0, 0, 1], angle: {}}}}}, ", num(alpha)) : "";
  std::string how = from(in, "power") + fmt::format(" {}", p) + (alpha != 0 ? ", alpha_angle_offset" : "") +
                    (beta != 0 ? ", beta_angle_offset" : "") + ": asin latitude";
  std::string c = add_c_step(in, adds_c(in, true));
  if (!c.empty()) c = ", " + c;
  if (beta == 0 && p % 4 == 1) return {fmt::format("{}{{bulb_power: {}}}{}", turn, p, c), how + ", the acos form's map", 60};
  if (beta == 0 && p % 4 == 3)
    return {fmt::format("{}{{scale: -1}}, {{bulb_power: {}}}{}", turn, p, c), how + ", the acos form of -z", 60};
  std::string steps = turn;
  int rest = p;
  for (int k : {2, 3})
    while (rest % k == 0) {
      steps += longitude_step(k) + ", ";
      rest /= k;
    }
  if (rest != 1) unsupported_setting(in, "power", num(power) + " (with a beta offset or even, powers 2^a 3^b map)");
  return {steps + latitude_step(p, beta) + c, how + " written out", 60};
}

Node mandelbulb(const FormulaInput& in) { return chain_formula(in, mandelbulb_chain(in)); }

// mandelbulb_power2.cl: the power-2 bulb with the new z negated.
ChainPart mandelbulb_power2_chain(const FormulaInput& in) {
  std::string f = fmt::format("(1 - z*z / {})", kRho2), c = add_c_step(in, adds_c(in, true));
  return {fmt::format("{{expr: {{x: \"(x*x - y*y)*{0}\", y: \"2*x*y*{0}\", z: \"-2*z*{1}\"}}}}", f, kRho) + (c.empty() ? "" : ", " + c),
          "mandelbulb_power2.cl's polynomials", 60};
}

Node mandelbulb_power2(const FormulaInput& in) { return chain_formula(in, mandelbulb_power2_chain(in)); }

}  // namespace sdfc::fract
