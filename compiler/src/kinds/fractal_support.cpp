// The parts the fractal descriptions share (fractal.hpp).
#include <fmt/format.h>

#include "../codegen/trap_shape_emitter.hpp"
#include "../frontend/animated_node.hpp"
#include "fractal.hpp"

namespace sdfc::kinds {

using codegen::detail::OrbitValue;
using frontend::MapReader;
using frontend::Param;
using frontend::Range;
using frontend::ValueReader;

std::string orbit_call(Emitter& e, std::string fn, const std::string& args, bool escapes) {
  if (e.shape) fn = codegen::detail::shaped_trap_fn(fn, *e.shape, e.used);  // a copy with the material's trap shape
  else e.used.insert(fn);
  // One orbit gives every value; the caller picks one.
  std::string t = fmt::format("otrap{}", e.w.fresh()), it = fmt::format("oiter{}", e.w.fresh());
  std::string count = escapes ? fmt::format("ocount{}", e.w.fresh()) : "";
  e.w.line(fmt::format("real {};", it));
  if (escapes) e.w.line(fmt::format("real {};", count));
  e.w.line(fmt::format("real {} = {}({}, &{}{});", t, fn, args, it, escapes ? ", &" + count : ""));
  return e.value == OrbitValue::Escape ? count : e.value == OrbitValue::Smooth ? it : t;
}

std::string bulb_estimator_radius(const Emitter& e, size_t power, size_t bailout) {
  const ir::Node& n = e.n;
  if (!n.animation(power) && !n.animation(bailout))
    return e.real(ir::bulb_estimator_radius(n.params.at(power), n.params.at(bailout)));
  return fmt::format("fmax({}, fmin({}, pow({}, {} / fmax({}, {}))))", e.param(bailout), e.real(64.0), e.real(2.0),
                     e.real(8.0), e.param(power), e.real(1.0));
}

double de_method(ValueReader& r, const MapReader& m, std::string_view what, std::initializer_list<ir::DeMethod> methods) {
  const SourceValue* v = m.get("de");
  if (!v) return double(ir::DeMethod::Analytic);
  std::vector<std::string_view> names;
  for (auto x : methods) names.push_back(ir::de_method_name(x));
  // `dual` is another name for `jacobian` (forward-mode dual numbers).
  if (v->is_scalar() && !v->quoted) {
    std::string word = v->scalar == "dual" ? "jacobian" : v->scalar;
    for (auto x : methods)
      if (word == ir::de_method_name(x)) return double(x);
  }
  std::string list;
  for (auto n : names) list += (list.empty() ? "" : ", ") + std::string(n);
  std::string hint = v->is_scalar() ? did_you_mean(v->scalar, names) : "";
  r.sink().error(v->loc, fmt::format("{}.de: '{}' is not a distance-estimation method of {}; it has: {}", what,
                                     v->is_scalar() ? v->scalar : v->kind_name(), what, list),
                 hint);
  return double(ir::DeMethod::Analytic);
}

// A Mandelbox scale must expand (|scale| > 1) or the set fills space.
Param mandelbox_scale(MapReader& m, const std::string& what, ValueReader& r) {
  Param scale = m.param("scale", -1.5, Range::closed(-8, 8));
  bool expands = scale.lo > 1.0 || scale.hi < -1.0;  // at every time
  if (!expands && m.get("scale"))
    r.sink().error(m.get("scale")->loc,
                   scale.animated() ? fmt::format("{}.scale: expected |scale| > 1 at every time, but it ranges over [{:g}, {:g}]", what, scale.lo, scale.hi)
                                    : fmt::format("{}.scale: expected |scale| > 1, got {}", what, scale.value),
                   "the Mandelbox needs an expanding scale such as 2 or -1.5");
  return expands ? scale : Param(-1.5);
}

std::pair<double, double> mandelbox_radii(MapReader& m, const std::string& what, ValueReader& r) {
  double min_r = m.number("min_radius", 0.5, Range::positive(100));
  double fixed_r = m.number("fixed_radius", 1.0, Range::positive(100));
  if (min_r >= fixed_r) {
    const SourceValue* at = m.get("min_radius") ? m.get("min_radius") : m.get("fixed_radius");
    r.sink().error(at ? at->loc : m.self().loc,
                   fmt::format("{}: min_radius ({}) must be less than fixed_radius ({})", what, min_r, fixed_r), "");
    return {0.5, 1.0};
  }
  return {min_r, fixed_r};
}

std::string de_words(ir::DeMethod method) {
  std::string what = std::string("de: ") + ir::de_method_name(method);
  if (method == ir::DeMethod::Jacobian) return what + ", near-exact (can overshoot slightly: no conservative term)";
  return what + ", bound in practice (not proven)";
}

namespace orbit {

double measure(const ir::TrapShape& t, const V3& z) {
  using K = ir::TrapShape::Kind;
  V3 q{z[0] - t.point[0], z[1] - t.point[1], z[2] - t.point[2]};
  V3 d{t.direction[0], t.direction[1], t.direction[2]};
  switch (t.kind) {
    case K::Point: return len(q);
    case K::Plane: return std::fabs(dot(q, d));
    case K::Line: return std::sqrt(std::max(dot(q, q) - dot(q, d) * dot(q, d), 0.0));
    case K::Sphere: return std::fabs(len(q) - t.radius);
    case K::Cross: break;
  }
  return std::min({std::fabs(z[0]), std::fabs(z[1]), std::fabs(z[2])});
}

double smooth_iteration(int n, double r, double R, double g, bool power_law, int iterations) {
  if (r < R) return 1.0;
  double lR = std::log(std::max(R, 1.0001));
  double frac = power_law ? std::log(std::log(std::max(r, 1.0001)) / lR) : std::log(r / R);
  frac = std::clamp(frac / std::log(std::max(g, 1.0001)), 0.0, 1.0);
  return (n - frac) / iterations;
}

V3 bulb_power(const V3& z, double n, double* r_pow_n_minus_1) {
  double r = std::max(len(z), 1e-20);
  double theta = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * n;
  double phi = std::atan2(z[1], z[0]) * n;
  double rp = std::pow(r, n - 1);
  *r_pow_n_minus_1 = rp;
  double rn = rp * r;
  return {rn * std::sin(theta) * std::cos(phi), rn * std::sin(theta) * std::sin(phi), rn * std::cos(theta)};
}

V3 bulb(const V3& z, double power) {
  double r = std::max(len(z), 1e-20);
  double th = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * power, ph = std::atan2(z[1], z[0]) * power;
  double rn = std::pow(r, power);
  return {rn * std::sin(th) * std::cos(ph), rn * std::sin(th) * std::sin(ph), rn * std::cos(th)};
}

double box_sphere_fold(V3& z, double fl, double min_r, double fixed_r) {
  for (double& c : z) {
    if (c > fl) c = 2 * fl - c;
    else if (c < -fl) c = -2 * fl - c;
  }
  double r2 = dot(z, z), f = 1;
  if (r2 < min_r * min_r) f = (fixed_r * fixed_r) / (min_r * min_r);
  else if (r2 < fixed_r * fixed_r) f = (fixed_r * fixed_r) / r2;
  for (double& c : z) c *= f;
  return f;
}

void sort_descending(V3& z) {
  for (double& c : z) c = std::fabs(c);
  std::sort(z.begin(), z.end(), [](double a, double b) { return a > b; });
}

void tetra_folds(V3& z) {
  if (z[0] + z[1] < 0) z = {-z[1], -z[0], z[2]};
  if (z[0] + z[2] < 0) z = {-z[2], z[1], -z[0]};
  if (z[1] + z[2] < 0) z = {z[0], -z[2], -z[1]};
}

}  // namespace orbit

}  // namespace sdfc::kinds
