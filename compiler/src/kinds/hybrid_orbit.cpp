#include "hybrid_orbit.hpp"

#include <fmt/format.h>

#include "../codegen/trap_shape_emitter.hpp"

namespace sdfc::kinds::hybrid {

namespace {

// A hybrid's orbit: its iteration budget, the length of its step pattern and
// its escape radius.
struct Orbit {
  int iterations, steps, period = 0;
  std::string escape;
};

Orbit orbit_of(const HybridP& h, const Emitter& e) {
  Orbit o{int(h.iterations), int(h.steps), 0, e.real(ir::hybrid_escape_radius(h.bailout))};
  for (int s = 0; s < o.steps; ++s) o.period += int(h.step[size_t(s)].repeat);
  return o;
}

// The step pattern inside a hybrid's orbit loop: one branch per step on k
// (the position in the pattern), setting z_next from z and scaling `dr`.
// With `growth`, each branch also records the step's growth g and law (1: a
// power, 0: linear) for the smooth iteration count.
void steps(const HybridP& h, Emitter& e, const std::string& dr, bool growth) {
  int count = int(h.steps), upto = 0;
  for (int s = 0; s < count; ++s) {
    const StepP& st = h.step[size_t(s)];
    upto += int(st.repeat);
    // The last step is the else branch; a one-step hybrid has no branch at all.
    std::string cond = s + 1 == count ? (s ? "else" : "") : fmt::format("{}if (k < {})", s ? "else " : "", upto);
    const bool bulb = st.formula == double(ir::HybridStep::Mandelbulb);
    // a whole power goes without trigonometry, as the Mandelbulb kind's does (five times faster)
    const bool whole = bulb && integer_power(st.power_or_scale);
    e.used.insert(whole ? "fold_hybrid_bulb_int" : bulb ? "fold_hybrid_bulb" : "fold_hybrid_box");
    std::string call = whole  ? fmt::format("fold_hybrid_bulb_int(z, {}, {}, &{})", int(st.power_or_scale), e.p, dr)
                       : bulb ? fmt::format("fold_hybrid_bulb(z, {}, {}, &{})", e.real(st.power_or_scale), e.p, dr)
                              : fmt::format("fold_hybrid_box(z, {}, {}, {}, {}, {}, &{})", e.real(st.power_or_scale),
                                          e.real(st.min_radius * st.min_radius),
                                          e.real(st.fixed_radius * st.fixed_radius), e.real(st.folding_limit), e.p, dr);
    if (growth)
      e.w.line(fmt::format("{} {{ z_next = {}; g = {}; law = {}; }}", cond, call,
                           e.real(bulb ? st.power_or_scale : std::fabs(st.power_or_scale)), bulb ? "1.0f" : "0.0f"));
    else
      e.w.line(fmt::format("{} z_next = {};  // {} {}", cond, call, bulb ? "mandelbulb power" : "mandelbox scale",
                           st.power_or_scale));
  }
}

}  // namespace

std::string emit(Emitter& e) {
  auto h = view<HybridP>(e.n);
  const Orbit o = orbit_of(h, e);
  auto& w = e.w;
  std::string d = fmt::format("hyb{}", w.fresh());
  w.line(fmt::format("real {};  // hybrid orbit: {} iterations, the step pattern repeats every {}", d, o.iterations, o.period));
  w.open("{");
  w.line(fmt::format("vec3 z = {};", e.p));
  w.line("real dr = 1.0f;");
  w.line("real r = v3_length(z);");
  w.line(fmt::format("mask alive = r < {};  // the escape radius, not the bailout: see ir::hybrid_escape_radius", o.escape));
  w.open(fmt::format("for (int i = 0; i < {} && M_ANY(alive); ++i) {{", o.iterations));
  w.line(fmt::format("const int k = i % {};  // the same step for every lane", o.period));
  w.line("real dr_next = dr;");
  w.line("vec3 z_next;");
  steps(h, e, "dr_next", false);
  w.line("z = v3_select(z, z_next, alive);");
  w.line("dr = SEL(dr, dr_next, alive);");
  w.line("r = v3_length(z);");
  w.line(fmt::format("alive = alive & (r < {});", o.escape));
  w.close("}");
  w.line(fmt::format("{} = r / fabs(dr);  // the linear estimator: below the log one at the escape radius", d));
  w.line("// far field: the set lies inside the bailout ball, so beyond twice its radius the distance to");
  w.line("// the ball is a true bound and a longer step");
  w.line(fmt::format("real r0 = v3_length({});", e.p));
  w.line(fmt::format("{0} = SEL({0}, r0 - {1}, r0 > {2});", d, e.real(h.bailout), e.real(2 * h.bailout)));
  w.close("}");
  return d;
}

// The hybrid's orbit trap and smooth iteration count, written inline like its
// estimator: the same step pattern, the trap (smallest |coordinate|) and the
// steps taken; the fraction past the escape radius follows the growth law of
// the step that escaped (a power for a Mandelbulb step, linear for a box).
std::string emit_trap(Emitter& e) {
  auto h = view<HybridP>(e.n);
  const Orbit o = orbit_of(h, e);
  const bool iteration = e.value == codegen::detail::OrbitValue::Smooth;
  const std::string measure = e.shape ? codegen::detail::trap_measure_call(*e.shape, "z", e.used)
                                      : "fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))";
  const std::string& escape = o.escape;
  auto& w = e.w;
  std::string out = fmt::format("htrap{}", w.fresh());
  w.line(fmt::format("real {};  // hybrid orbit {}", out, iteration ? "smooth iteration count" : "trap"));
  w.open("{");
  w.line(fmt::format("vec3 z = {};", e.p));
  w.line("real dr = 1.0f, trap = 1e10f, n = 0.0f, growth = 2.0f, power_law = 0.0f;");
  w.line("real r = v3_length(z);");
  w.line(fmt::format("mask alive = r < {};", escape));
  w.open(fmt::format("for (int i = 0; i < {} && M_ANY(alive); ++i) {{", o.iterations));
  w.line(fmt::format("const int k = i % {};", o.period));
  w.line("vec3 z_next;");
  w.line("real g, law;");
  steps(h, e, "dr", true);
  w.line("z = v3_select(z, z_next, alive);");
  w.line("n = SEL(n, n + 1.0f, alive);");
  w.line("growth = SEL(growth, (real)(g), alive);");
  w.line("power_law = SEL(power_law, (real)(law), alive);");
  w.line("trap = SEL(trap, fmin(trap, " + measure + "), alive);");
  w.line("r = v3_length(z);");
  w.line(fmt::format("alive = alive & (r < {});", escape));
  w.close("}");
  if (iteration) {
    w.line(fmt::format("real rr = fmax(r, {0}), lR = log({0});", escape));
    w.line("real frac = SEL(log(rr / " + escape + "), log(log(rr) / lR), power_law > 0.5f);");
    w.line("frac = clamp(frac / log(fmax(growth, K(1.0001f))), K(0.0f), K(1.0f));");
    w.line(fmt::format("{} = SEL((real)(1.0f), (n - frac) / {}, r >= {});", out, e.real(double(o.iterations)), escape));
  } else {
    w.line(fmt::format("{} = trap;", out));
  }
  w.close("}");
  return out;
}

}  // namespace sdfc::kinds::hybrid
