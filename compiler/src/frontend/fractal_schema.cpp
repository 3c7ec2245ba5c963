// Fractal nodes: parameters, defaults and validation. The defaults are the
// classic settings of each formula (seeds 000 and 001), so `{mandelbox: {}}`
// already renders the familiar shape.
#include "fractal_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "animated_node.hpp"
#include "sdfc/ir/fractal_math.hpp"

namespace sdfc::frontend {

using ir::Kind;
using ir::NodeId;

const std::vector<std::string_view>& fractal_kinds() {
  static const std::vector<std::string_view> k = {"mandelbulb", "mandelbox", "julia", "menger",
                                                  "sierpinski", "kifs",      "hybrid"};
  return k;
}

namespace {

double norm(const Vec3d& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

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

// min_radius < fixed_radius, both positive.
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

// `de: METHOD`, one of `methods` (the node's own); the error names them.
// `dual` is another name for `jacobian` (forward-mode dual numbers).
double de_method(ValueReader& r, const MapReader& m, std::string_view what,
                 std::initializer_list<ir::DeMethod> methods) {
  const SourceValue* v = m.get("de");
  if (!v) return double(ir::DeMethod::Analytic);
  std::vector<std::string_view> names;
  for (auto x : methods) names.push_back(ir::de_method_name(x));
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

NodeId mandelbulb(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "mandelbulb", {"power", "iterations", "bailout", "julia", "de"});
  Param power = m.param("power", 8.0, Range::closed(1, 64));
  int iterations = m.integer("iterations", 10, 1, 1000);
  Param bailout = m.param("bailout", 2.0, {0, 1e3, true});
  if (!m.get("julia")) {
    double method = de_method(r, m, "mandelbulb", {ir::DeMethod::Analytic, ir::DeMethod::Gradient,
                                                   ir::DeMethod::Potential, ir::DeMethod::SinhPotential});
    return make_node(b, Kind::Mandelbulb, {power, double(iterations), bailout, method}, {}, at);
  }
  de_method(r, m, "mandelbulb with julia", {ir::DeMethod::Analytic});
  if (power.lo < 2) {
    r.sink().error(m.get("power") ? m.get("power")->loc : at, fmt::format("mandelbulb.power: a Juliabulb needs power >= 2, got {}", power.lo), "");
    return ir::kNoNode;
  }
  // The Juliabulb's far field needs the root of R^power - R - |c|, found at
  // compile time, so its power stays static.
  if (power.animated()) {
    r.sink().error(m.get("power")->loc, "mandelbulb.power cannot be animated in a Juliabulb (with julia)", "animate the power of a plain mandelbulb");
    return ir::kNoNode;
  }
  Vec3d c = m.vec3("julia", {0, 0, 0}, Range::closed(-4, 4));
  return make_node(b, Kind::Juliabulb, {power, double(iterations), bailout, c[0], c[1], c[2]}, {}, at);
}

NodeId mandelbox(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  std::string what = "mandelbox";
  MapReader m(r, body, what, {"scale", "min_radius", "fixed_radius", "folding_limit", "iterations", "julia", "scale_xyz", "de"});
  double method = de_method(r, m, what, {ir::DeMethod::Analytic, ir::DeMethod::Jacobian});
  Param scale = mandelbox_scale(m, what, r);
  auto [min_r, fixed_r] = mandelbox_radii(m, what, r);
  double fl = m.number("folding_limit", 1.0, Range::positive(100));
  int iterations = m.integer("iterations", 12, 1, 200);
  bool julia = m.get("julia") != nullptr;
  Vec3d c = m.vec3("julia", {0, 0, 0}, Range::closed(-10, 10));
  Vec3d s = m.vec3("scale_xyz", {1, 1, 1}, Range::closed(0.25, 4));
  double smallest = std::min(std::fabs(scale.lo), std::fabs(scale.hi)) * std::min({s[0], s[1], s[2]});
  if (smallest <= 1.0 && m.get("scale_xyz")) {
    r.sink().error(m.get("scale_xyz")->loc,
                   fmt::format("mandelbox.scale_xyz: |scale| x the smallest factor is {:.3g}, but must be > 1", smallest),
                   "every axis must still expand; raise the smallest factor");
    s = {1, 1, 1};
  }
  return make_node(b, Kind::Mandelbox, {scale, min_r, fixed_r, fl, double(iterations), julia ? 1.0 : 0.0, c[0], c[1], c[2],
                                       s[0], s[1], s[2], method}, {}, at);
}

NodeId julia(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "julia", {"c", "degree", "iterations", "slice", "bailout", "de"});
  de_method(r, m, "julia", {ir::DeMethod::Analytic});
  std::vector<double> c = {-0.2, 0.6, 0.2, 0.2};
  if (const SourceValue* cv = m.get("c")) c = r.vecn(*cv, "julia.c", 4, Range::closed(-4, 4));
  int degree = m.integer("degree", 2, 2, 3);
  int iterations = m.integer("iterations", 12, 1, 1000);
  double slice = m.number("slice", 0.0, Range::closed(-4, 4));
  double bailout = m.number("bailout", 4.0, {1, 1e3, true});
  return b.make(Kind::QuaternionJulia, {c[0], c[1], c[2], c[3], double(degree), double(iterations), slice, bailout}, {}, at);
}

NodeId menger(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "menger", {"iterations", "scale", "de"});
  de_method(r, m, "menger", {ir::DeMethod::Analytic});
  int iterations = m.integer("iterations", 4, 1, 12);
  Param scale = m.param("scale", 3.0, Range::closed(2, 4));
  return make_node(b, Kind::Menger, {double(iterations), scale}, {}, at);
}

NodeId sierpinski(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "sierpinski", {"iterations", "scale", "de"});
  de_method(r, m, "sierpinski", {ir::DeMethod::Analytic});
  int iterations = m.integer("iterations", 8, 1, 30);
  Param scale = m.param("scale", 2.0, {1, 4, true});
  return make_node(b, Kind::Sierpinski, {double(iterations), scale}, {}, at);
}

std::array<double, 9> rotation(ValueReader& r, const MapReader& m, std::string_view key) {
  const SourceValue* v = m.get(key);
  if (!v) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  MapReader rm(r, *v, fmt::format("kifs.{}", key), {"axis", "degrees"});
  Vec3d axis = rm.require("axis") ? rm.direction("axis", {0, 0, 1}) : Vec3d{0, 0, 1};
  double deg = rm.require("degrees") ? rm.number("degrees", 0, Range::closed(-36000, 36000)) : 0;
  return ir::axis_rotation(axis, deg);
}

NodeId kifs(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "kifs", {"symmetry", "scale", "offset", "rotate_before", "rotate_after", "iterations", "de"});
  de_method(r, m, "kifs", {ir::DeMethod::Analytic});
  std::string sym = m.word("symmetry", "tetrahedral", {"tetrahedral", "octahedral", "icosahedral", "menger"});
  double code = sym == "tetrahedral" ? 0 : sym == "octahedral" ? 1 : sym == "icosahedral" ? 2 : 3;
  double scale = m.number("scale", 2.0, {1, 4, true});
  Vec3d offset = m.vec3("offset", {1, 1, 1}, Range::closed(-10, 10));
  if (norm(offset) < 1e-6) {
    r.sink().error(m.get("offset")->loc, "kifs.offset: must not be zero (it is the scaling centre)", "");
    offset = {1, 1, 1};
  }
  int iterations = m.integer("iterations", 12, 1, 40);
  std::vector<double> p = {code, scale, offset[0], offset[1], offset[2], double(iterations)};
  auto before = rotation(r, m, "rotate_before"), after = rotation(r, m, "rotate_after");
  p.insert(p.end(), before.begin(), before.end());
  p.insert(p.end(), after.begin(), after.end());
  return b.make(Kind::Kifs, std::move(p), {}, at);
}

// {mandelbulb: {power}} or {mandelbox: {scale, min_radius, fixed_radius, folding_limit}}.
bool hybrid_step(ValueReader& r, const SourceValue& v, std::vector<double>& out) {
  if (!v.is_map() || v.entries.size() != 1) {
    r.sink().error(v.loc, "hybrid.steps: each step is one formula, '{mandelbulb: {...}}' or '{mandelbox: {...}}'", "");
    return false;
  }
  const auto& [k, body] = v.entries.front();
  if (k.scalar == "mandelbulb") {
    MapReader m(r, body, "hybrid mandelbulb step", {"power"});
    out.insert(out.end(), {double(ir::HybridStep::Mandelbulb), 1, m.number("power", 8.0, Range::closed(2, 32)), 0, 0, 0});
    return true;
  }
  if (k.scalar == "mandelbox") {
    std::string what = "hybrid mandelbox step";
    MapReader m(r, body, what, {"scale", "min_radius", "fixed_radius", "folding_limit"});
    Param sp = mandelbox_scale(m, what, r);
    if (sp.animated()) r.sink().error(m.get("scale")->loc, what + ".scale cannot be animated", "animate a mandelbox node's scale instead");
    double scale = sp.value;
    auto [min_r, fixed_r] = mandelbox_radii(m, what, r);
    double fl = m.number("folding_limit", 1.0, Range::positive(100));
    out.insert(out.end(), {double(ir::HybridStep::Mandelbox), 1, scale, min_r, fixed_r, fl});
    return true;
  }
  std::string hint = did_you_mean(k.scalar, {"mandelbulb", "mandelbox"});
  r.sink().error(k.loc, fmt::format("hybrid.steps: unknown formula '{}'", k.scalar),
                 hint.empty() ? "a step is 'mandelbulb' or 'mandelbox'" : hint);
  return false;
}

NodeId hybrid(ValueReader& r, ir::Builder& b, const SourceValue& body, const SourceLoc& at) {
  MapReader m(r, body, "hybrid", {"steps", "repeat", "iterations", "bailout", "de"});
  de_method(r, m, "hybrid", {ir::DeMethod::Analytic});
  const SourceValue* steps = m.require("steps");
  int iterations = m.integer("iterations", 12, 1, 200);
  double bailout = m.number("bailout", 10.0, {1, 1e3, true});
  if (!steps) return ir::kNoNode;
  if (!steps->is_seq() || steps->items.empty() || steps->items.size() > size_t(ir::kHybridMaxSteps)) {
    r.sink().error(steps->loc, fmt::format("hybrid.steps: expected a list of 1 to {} formulas", ir::kHybridMaxSteps), "");
    return ir::kNoNode;
  }
  size_t n = steps->items.size();
  std::vector<double> p = {double(iterations), bailout, double(n)};
  for (const auto& s : steps->items)
    if (!hybrid_step(r, s, p)) return ir::kNoNode;
  if (const SourceValue* rep = m.get("repeat")) {
    if (!rep->is_seq() || rep->items.size() != n) {
      r.sink().error(rep->loc, fmt::format("hybrid.repeat: expected a list of {} whole numbers, one per step", n), "");
      return ir::kNoNode;
    }
    for (size_t i = 0; i < n; ++i)
      p[3 + i * ir::kHybridStepParams + 1] = r.integer(rep->items[i], "hybrid.repeat", 1, 20);
  }
  p.resize(3 + ir::kHybridMaxSteps * ir::kHybridStepParams, 0.0);
  return b.make(Kind::Hybrid, std::move(p), {}, at);
}

}  // namespace

NodeId lower_fractal(ValueReader& r, ir::Builder& b, const SourceValue& key, const SourceValue& body) {
  const std::string& k = key.scalar;
  if (k == "mandelbulb") return mandelbulb(r, b, body, key.loc);
  if (k == "mandelbox") return mandelbox(r, b, body, key.loc);
  if (k == "julia") return julia(r, b, body, key.loc);
  if (k == "menger") return menger(r, b, body, key.loc);
  if (k == "sierpinski") return sierpinski(r, b, body, key.loc);
  if (k == "kifs") return kifs(r, b, body, key.loc);
  if (k == "hybrid") return hybrid(r, b, body, key.loc);
  return ir::kNoNode;
}

}  // namespace sdfc::frontend
