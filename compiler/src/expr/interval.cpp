// Interval arithmetic over expressions: a conservative range of values for
// variables in given ranges. Used to bound gradients (Lipschitz constants)
// of displacement expressions over a node's bounding box.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sdfc/expr/expr.hpp"

namespace sdfc::expr {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const Interval kEverything{-kInf, kInf};

Interval hull(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

Interval mul(Interval a, Interval b) {
  double c[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  Interval r{kInf, -kInf};
  for (double v : c) {
    if (std::isnan(v)) v = 0;  // 0 * inf: the product of a zero factor
    r.lo = std::min(r.lo, v), r.hi = std::max(r.hi, v);
  }
  return r;
}

Interval div(Interval a, Interval b) {
  if (b.lo <= 0 && b.hi >= 0) return kEverything;
  return mul(a, {1 / b.hi, 1 / b.lo});
}

// sin over [lo, hi]: the endpoints, plus +-1 wherever a peak lies inside.
Interval sine(Interval x, double phase) {
  if (!std::isfinite(x.lo) || !std::isfinite(x.hi) || x.hi - x.lo >= 2 * std::numbers::pi) return {-1, 1};
  double a = std::sin(x.lo + phase), b = std::sin(x.hi + phase);
  Interval r{std::min(a, b), std::max(a, b)};
  // Peaks of sin(t + phase) at t = pi/2 - phase + 2k pi; troughs at -pi/2 - phase + 2k pi.
  auto contains_point = [&](double base) {
    double k = std::ceil((x.lo - base) / (2 * std::numbers::pi));
    return base + k * 2 * std::numbers::pi <= x.hi;
  };
  if (contains_point(std::numbers::pi / 2 - phase)) r.hi = 1;
  if (contains_point(-std::numbers::pi / 2 - phase)) r.lo = -1;
  return r;
}

Interval monotone(Interval x, double (*f)(double)) { return {f(x.lo), f(x.hi)}; }

Interval power(Interval x, Interval y) {
  if (y.lo == y.hi && y.lo == std::floor(y.lo) && std::fabs(y.lo) <= 64) {
    int n = static_cast<int>(y.lo);
    if (n == 0) return {1, 1};
    if (n < 0) return div({1, 1}, power(x, {double(-n), double(-n)}));
    double a = std::pow(x.lo, n), b = std::pow(x.hi, n);
    if (n % 2 == 1) return {a, b};
    if (x.lo >= 0) return {a, b};
    if (x.hi <= 0) return {b, a};
    return {0, std::max(a, b)};
  }
  if (x.lo <= 0) return kEverything;  // pow of a non-positive base to a real power
  // x^y = exp(y log x), both monotone pieces.
  Interval l = monotone(x, [](double v) { return std::log(v); });
  Interval p = mul(y, l);
  return {std::exp(p.lo), std::exp(p.hi)};
}

}  // namespace

double Interval::magnitude() const { return std::max(std::fabs(lo), std::fabs(hi)); }

Interval evaluate_interval(const ExprPtr& e, const IntervalEnv& vars) {
  auto arg = [&](size_t i) { return evaluate_interval(e->args[i], vars); };
  switch (e->op) {
    case Op::Number: return {e->value, e->value};
    case Op::Slot: return {e->lo, e->hi};
    case Op::Var: {
      auto it = vars.find(e->name);
      if (it == vars.end()) throw std::logic_error("expression variable '" + e->name + "' has no range");
      return it->second;
    }
    case Op::Neg: {
      Interval a = arg(0);
      return {-a.hi, -a.lo};
    }
    case Op::Add: {
      Interval a = arg(0), b = arg(1);
      return {a.lo + b.lo, a.hi + b.hi};
    }
    case Op::Sub: {
      Interval a = arg(0), b = arg(1);
      return {a.lo - b.hi, a.hi - b.lo};
    }
    case Op::Mul: return mul(arg(0), arg(1));
    case Op::Div: return div(arg(0), arg(1));
    case Op::Pow: return power(arg(0), arg(1));
    case Op::Call: {
      const std::string& f = e->name;
      Interval a = arg(0);
      if (f == "sin") return sine(a, 0);
      if (f == "cos") return sine(a, std::numbers::pi / 2);
      if (f == "tan") {
        // Monotone between poles at pi/2 + k pi.
        double k = std::ceil((a.lo - std::numbers::pi / 2) / std::numbers::pi);
        if (std::numbers::pi / 2 + k * std::numbers::pi <= a.hi || !std::isfinite(a.lo) || !std::isfinite(a.hi)) return kEverything;
        return {std::tan(a.lo), std::tan(a.hi)};
      }
      if (f == "exp") return monotone(a, [](double v) { return std::exp(v); });
      if (f == "log") return a.lo <= 0 ? Interval{-kInf, a.hi > 0 ? std::log(a.hi) : -kInf} : monotone(a, [](double v) { return std::log(v); });
      if (f == "sqrt") return {std::sqrt(std::max(a.lo, 0.0)), std::sqrt(std::max(a.hi, 0.0))};
      if (f == "abs") return a.lo >= 0 ? a : a.hi <= 0 ? Interval{-a.hi, -a.lo} : Interval{0, std::max(-a.lo, a.hi)};
      if (f == "sgn") return {a.lo > 0 ? 1.0 : a.lo == 0 ? 0.0 : -1.0, a.hi < 0 ? -1.0 : a.hi == 0 ? 0.0 : 1.0};
      Interval b = arg(1);
      if (f == "min") return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
      if (f == "max") return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
      if (f == "hull") return hull(a, b);
      Interval c = arg(2);
      if (f == "clamp") {
        Interval lo{std::min(b.lo, c.lo), std::min(b.hi, c.hi)}, hi{std::max(b.lo, c.lo), std::max(b.hi, c.hi)};
        return {std::min(std::max(a.lo, lo.lo), hi.hi), std::max(std::min(a.hi, hi.hi), lo.lo)};
      }
      if (f == "mix") {  // a + (b - a) * t
        Interval d{b.lo - a.hi, b.hi - a.lo};
        Interval m = mul(d, c);
        return {a.lo + m.lo, a.hi + m.hi};
      }
      if (f == "smoothstep") return {0, 1};
      throw std::logic_error("no interval rule for " + f);
    }
  }
  return kEverything;
}

}  // namespace sdfc::expr
