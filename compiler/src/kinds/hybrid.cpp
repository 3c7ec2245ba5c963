// hybrid: up to four formula steps (Mandelbulb powers and Mandelbox folds)
// taken in a repeating pattern along one orbit.
#include <fmt/format.h>

#include "fractal.hpp"
#include "hybrid_orbit.hpp"

SDFC_KIND(Hybrid, 24, "hybrid", Fractal, 0, "iterations,bailout,steps,k0,n0,a0,b0,c0,d0,k1,n1,a1,b1,c1,d1,k2,n2,a2,b2,c2,d2,k3,n3,a3,b3,c3,d3", "")

namespace sdfc::kinds {
namespace {
using frontend::MapReader;
using frontend::Range;
using hybrid::HybridP;
using hybrid::StepP;

// {mandelbulb: {power}} or {mandelbox: {scale, min_radius, fixed_radius, folding_limit}}.
bool lower_step(frontend::ValueReader& r, const SourceValue& v, StepP& out) {
  if (!v.is_map() || v.entries.size() != 1) {
    r.sink().error(v.loc, "hybrid.steps: each step is one formula, '{mandelbulb: {...}}' or '{mandelbox: {...}}'", "");
    return false;
  }
  const auto& [k, body] = v.entries.front();
  if (k.scalar == "mandelbulb") {
    MapReader m(r, body, "hybrid mandelbulb step", {"power"});
    out = {double(ir::HybridStep::Mandelbulb), 1, m.number("power", 8.0, Range::closed(2, 32)), 0, 0, 0};
    return true;
  }
  if (k.scalar == "mandelbox") {
    std::string what = "hybrid mandelbox step";
    MapReader m(r, body, what, {"scale", "min_radius", "fixed_radius", "folding_limit"});
    frontend::Param sp = mandelbox_scale(m, what, r);
    if (sp.animated()) r.sink().error(m.get("scale")->loc, what + ".scale cannot be animated", "animate a mandelbox node's scale instead");
    double scale = sp.value;
    auto [min_r, fixed_r] = mandelbox_radii(m, what, r);
    double fl = m.number("folding_limit", 1.0, Range::positive(100));
    out = {double(ir::HybridStep::Mandelbox), 1, scale, min_r, fixed_r, fl};
    return true;
  }
  std::string hint = did_you_mean(k.scalar, {"mandelbulb", "mandelbox"});
  r.sink().error(k.loc, fmt::format("hybrid.steps: unknown formula '{}'", k.scalar),
                 hint.empty() ? "a step is 'mandelbulb' or 'mandelbox'" : hint);
  return false;
}

ir::NodeId lower(Lowering& l) {
  frontend::ValueReader& r = l.reader();
  MapReader m(r, l.body(), "hybrid", {"steps", "repeat", "iterations", "bailout", "de"});
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
  HybridP h{double(iterations), bailout, double(n), {}};  // unused steps stay zero
  for (size_t i = 0; i < n; ++i)
    if (!lower_step(r, steps->items[i], h.step[i])) return ir::kNoNode;
  if (const SourceValue* rep = m.get("repeat")) {
    if (!rep->is_seq() || rep->items.size() != n) {
      r.sink().error(rep->loc, fmt::format("hybrid.repeat: expected a list of {} whole numbers, one per step", n), "");
      return ir::kNoNode;
    }
    for (size_t i = 0; i < n; ++i) h.step[i].repeat = r.integer(rep->items[i], "hybrid.repeat", 1, 20);
  }
  return l.make(h);
}

ir::Props props(const ir::Node& n) {
  // Points beyond the bailout have escaped before the first step.
  auto h = view<HybridP>(n);
  return estimate(h.bailout, 10 + h.iterations * 45);
}

std::string emit_orbit(Emitter& e) {
  // A hybrid reports its budget as its escape step.
  if (e.value == codegen::detail::OrbitValue::Escape) return e.lit.typed(view<HybridP>(e.n).iterations);
  return hybrid::emit_trap(e);
}

// The orbit's step sequence: each step `repeat` times, then around again.
std::vector<int> pattern(const HybridP& h) {
  std::vector<int> out;
  for (int s = 0; s < int(h.steps); ++s)
    for (int k = 0; k < int(h.step[size_t(s)].repeat); ++k) out.push_back(s);
  return out;
}

double distance(const ir::Node& n, const V3& p) {
  auto h = view<HybridP>(n);
  std::vector<int> steps = pattern(h);
  V3 z = p;
  double dr = 1, r = orbit::len(z);
  const double escape = ir::hybrid_escape_radius(h.bailout);
  for (int i = 0; i < int(h.iterations) && r < escape; ++i) {
    const StepP& st = h.step[size_t(steps[size_t(i) % steps.size()])];
    if (st.formula == double(ir::HybridStep::Mandelbulb)) {
      double rp;
      V3 zn = orbit::bulb_power(z, st.power_or_scale, &rp);
      dr = st.power_or_scale * rp * dr + 1;
      for (int k = 0; k < 3; ++k) z[k] = zn[k] + p[k];
    } else {
      double f = orbit::box_sphere_fold(z, st.folding_limit, st.min_radius, st.fixed_radius);
      dr = dr * std::fabs(st.power_or_scale) * f + 1;
      for (int k = 0; k < 3; ++k) z[k] = st.power_or_scale * z[k] + p[k];
    }
    r = orbit::len(z);
  }
  double r0 = orbit::len(p);
  if (r0 > 2 * h.bailout) return r0 - h.bailout;  // the set lies inside the bailout ball
  return r / std::fabs(dr);
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  auto h = view<HybridP>(n);
  int iterations = int(h.iterations), k = 0;
  std::vector<int> steps = pattern(h);
  const double escape = ir::hybrid_escape_radius(h.bailout);
  V3 z = p;
  double growth = 2, trap = 1e10;
  bool power_law = false;
  for (; k < iterations && orbit::len(z) < escape; ++k) {
    const StepP& st = h.step[size_t(steps[size_t(k) % steps.size()])];
    if (st.formula == double(ir::HybridStep::Mandelbulb)) {
      z = orbit::bulb(z, st.power_or_scale);
      growth = st.power_or_scale, power_law = true;
    } else {
      orbit::box_sphere_fold(z, st.folding_limit, st.min_radius, st.fixed_radius);
      for (double& c : z) c *= st.power_or_scale;
      growth = std::fabs(st.power_or_scale), power_law = false;
    }
    for (int i = 0; i < 3; ++i) z[i] += p[i];
    trap = std::min(trap, orbit::measure(shape, z));
  }
  return {trap, orbit::smooth_iteration(k, orbit::len(z), escape, growth, power_law, iterations)};
}

std::string de_summary(const ir::Node&) {
  return "de: analytic, bound in practice (linear estimator r / dr at escape radius 100, not proven)";
}

static constexpr ParamDoc k_docs[] = {
    {"steps", "list of 1 to 4 formulas", "", "",
     "each {mandelbulb: {power}} (2 to 32) or {mandelbox: {scale, min_radius, fixed_radius, folding_limit}}"},
    {"repeat", "list of whole numbers", "[1, 1]", "1 to 20, one per step", "how many times each step runs in turn (1 for each step; the default shown is for two steps)"},
    {"iterations", "integer", "12", "1 to 200", "orbit steps in all"},
    {"bailout", "number", "10", "> 1, up to 1000", "the ball that holds the set"},
    {"de", "one of analytic", "analytic", "", "the distance estimator"},
};

}  // namespace

namespace described {
extern const Description Hybrid{
    .kind = ir::Kind::Hybrid, .yaml = "hybrid",
    .example = "{hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}]}}",
    .param_count = count_of<HybridP>(), .lower = lower, .props = props, .call_args = {}, .distance = distance,
    .emit = hybrid::emit, .emit_orbit = emit_orbit, .orbit_colour = orbit_colour, .de_summary = de_summary,
    .bounds_trust = 1.0, .escape_time = true, .summary = "an estimate (a bound in practice, not proven)", .docs = k_docs};
}

}  // namespace sdfc::kinds
