#include "fractal_emitter.hpp"

#include <fmt/format.h>

#include <cmath>

#include "sdfc/formula/emit.hpp"
#include "sdfc/ir/fractal_math.hpp"
#include "trap_shape_emitter.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;

// A power the trig-free path can take: a whole number from 2 up.
bool integer_power(double power) { return power >= 2 && power == std::floor(power); }

// A hybrid's orbit: its iteration budget, the length of its step pattern and
// its escape radius.
struct HybridOrbit {
  int iterations, steps, period = 0;
  std::string escape;
};

HybridOrbit hybrid_orbit(const ir::Node& n, const Literals& lit) {
  const auto& q = n.params;
  HybridOrbit h{int(q[0]), int(q[2]), 0, lit.real(ir::hybrid_escape_radius(q[1]))};
  for (int s = 0; s < h.steps; ++s) h.period += int(q[3 + s * ir::kHybridStepParams + 1]);
  return h;
}

// The step pattern inside a hybrid's orbit loop: one branch per step on k
// (the position in the pattern), setting z_next from z and scaling `dr`.
// With `growth`, each branch also records the step's growth g and law (1: a
// power, 0: linear) for the smooth iteration count.
void hybrid_steps(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                  std::set<std::string>& used, const std::string& dr, bool growth) {
  const auto& q = n.params;
  int steps = int(q[2]), upto = 0;
  for (int s = 0; s < steps; ++s) {
    const double* st = &q[3 + s * ir::kHybridStepParams];
    upto += int(st[1]);
    // The last step is the else branch; a one-step hybrid has no branch at all.
    std::string cond = s + 1 == steps ? (s ? "else" : "") : fmt::format("{}if (k < {})", s ? "else " : "", upto);
    const bool bulb = st[0] == double(ir::HybridStep::Mandelbulb);
    used.insert(bulb ? "hybrid_bulb_step" : "hybrid_box_step");
    std::string call = bulb ? fmt::format("hybrid_bulb_step(z, {}, {}, &{})", lit.real(st[2]), p, dr)
                            : fmt::format("hybrid_box_step(z, {}, {}, {}, {}, {}, &{})", lit.real(st[2]),
                                          lit.real(st[3] * st[3]), lit.real(st[4] * st[4]), lit.real(st[5]), p, dr);
    if (growth)
      w.line(fmt::format("{} {{ z_next = {}; g = {}; law = {}; }}", cond, call, lit.real(bulb ? st[2] : std::fabs(st[2])),
                         bulb ? "1.0f" : "0.0f"));
    else
      w.line(fmt::format("{} z_next = {};  // {} {}", cond, call, bulb ? "mandelbulb power" : "mandelbox scale", st[2]));
  }
}

std::string hybrid(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                   std::set<std::string>& used) {
  const auto& q = n.params;
  const HybridOrbit h = hybrid_orbit(n, lit);
  std::string d = fmt::format("hyb{}", w.fresh());
  w.line(fmt::format("real {};  // hybrid orbit: {} iterations, the step pattern repeats every {}", d, h.iterations, h.period));
  w.open("{");
  w.line(fmt::format("vec3 z = {};", p));
  w.line("real dr = 1.0f;");
  w.line("real r = v3_length(z);");
  w.line(fmt::format("mask alive = r < {};  // the escape radius, not the bailout: see ir::hybrid_escape_radius", h.escape));
  w.open(fmt::format("for (int i = 0; i < {} && M_ANY(alive); ++i) {{", h.iterations));
  w.line(fmt::format("const int k = i % {};  // the same step for every lane", h.period));
  w.line("real dr_next = dr;");
  w.line("vec3 z_next;");
  hybrid_steps(n, p, lit, w, used, "dr_next", false);
  w.line("z = v3_select(z, z_next, alive);");
  w.line("dr = SEL(dr, dr_next, alive);");
  w.line("r = v3_length(z);");
  w.line(fmt::format("alive = alive & (r < {});", h.escape));
  w.close("}");
  w.line(fmt::format("{} = r / fabs(dr);  // the linear estimator: below the log one at the escape radius", d));
  w.line("// far field: the set lies inside the bailout ball, so beyond twice its radius the distance to");
  w.line("// the ball is a true bound and a longer step");
  w.line(fmt::format("real r0 = v3_length({});", p));
  w.line(fmt::format("{0} = SEL({0}, r0 - {1}, r0 > {2});", d, lit.real(q[1]), lit.real(2 * q[1])));
  w.close("}");
  return d;
}

// The arguments after p that a fractal's estimator and its orbit-trap
// function both take ("" for the Mandelbulb forms and the hybrid, whose
// calls differ). The quaternion Julia's estimator adds its set radius.
std::string orbit_args(const ir::Node& n, const Literals& lit) {
  const auto& q = n.params;
  auto r = [&](size_t i) { return param(n, i, lit); };
  auto row = [&](size_t i) { return lit.vec3({q[i], q[i + 1], q[i + 2]}); };
  switch (n.kind) {
    case Kind::Mandelbox:
      return fmt::format("{}, {}, {}, {}, {}, {}, {}, {}", r(0), lit.real(q[1] * q[1]), lit.real(q[2] * q[2]), r(3),
                         int(q[4]), int(q[5]), row(6), row(9));
    case Kind::QuaternionJulia:
      return fmt::format("{}, {}, {}, {}, {}, {}", r(6), r(0), row(1), int(q[4]), int(q[5]), r(7));
    case Kind::Menger:
    case Kind::Sierpinski: return fmt::format("{}, {}", int(q[0]), r(1));
    case Kind::Kifs:
      return fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}, {}", int(q[0]), r(1), row(2), int(q[5]), row(6), row(9),
                         row(12), row(15), row(18), row(21));
    default: return "";
  }
}

}  // namespace

std::string bulb_estimator_radius(const ir::Node& n, const Literals& lit) {
  if (!n.animation(0) && !n.animation(2)) return lit.real(ir::bulb_estimator_radius(n.params[0], n.params[2]));
  return fmt::format("fmax({}, fmin({}, pow({}, {} / fmax({}, {}))))", param(n, 2, lit), lit.real(64.0), lit.real(2.0),
                     lit.real(8.0), param(n, 0, lit), lit.real(1.0));
}

bool is_fractal(const ir::Node& n) { return ir::info(n.kind).category == ir::Category::Fractal; }

std::string emit_fractal(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                         std::set<std::string>& used) {
  const auto& q = n.params;
  auto r = [&](size_t i) { return param(n, i, lit); };
  auto call = [&](const char* fn) {
    used.insert(fn);
    return std::string(fn);
  };
  switch (n.kind) {
    case Kind::Mandelbulb: {
      std::string radius = lit.real(ir::mandelbulb_set_radius(q[0]));
      // An animated power takes the trig formula (the trig-free one is
      // specialised to one whole power) and the radius of its set per frame,
      // as ir::mandelbulb_set_radius computes it.
      if (n.animation(0))
        radius = fmt::format("({0} <= {1} ? {2} : fmin({2}, pow({3}, {4} / ({0} - {4}))))", r(0), lit.real(1.25),
                             lit.real(4.0), lit.real(2.0), lit.real(1.0));
      int ipower = integer_power(q[0]) && !n.animation(0) ? int(q[0]) : 0;  // > 0: the trig-free power
      auto method = ir::DeMethod(int(q[3]));
      if (method != ir::DeMethod::Analytic)
        return fmt::format("{}({}, {}, {}, {}, {}, {}, {})  /* de: {} */", call("de_mandelbulb_numeric"), p, r(0),
                           ipower, int(q[1]), r(2), radius, int(q[3]), ir::de_method_name(method));
      if (ipower)  // trig-free: the angles' multiples come from complex powers
        return fmt::format("{}({}, {}, {}, {}, {}, 0, v3_splat(0.0f))", call("de_mandelbulb_int"), p, ipower,
                           int(q[1]), bulb_estimator_radius(n, lit), radius);
      return fmt::format("{}({}, {}, {}, {}, {})", call("de_mandelbulb"), p, r(0), int(q[1]), bulb_estimator_radius(n, lit),
                         radius);
    }
    case Kind::Juliabulb: {
      double cn = std::sqrt(q[3] * q[3] + q[4] * q[4] + q[5] * q[5]);
      std::string radius = lit.real(ir::julia_set_radius(q[0], cn));
      std::string c = lit.vec3({q[3], q[4], q[5]});
      if (integer_power(q[0]))
        return fmt::format("{}({}, {}, {}, {}, {}, 1, {})", call("de_mandelbulb_int"), p, int(q[0]), int(q[1]),
                           bulb_estimator_radius(n, lit), radius, c);
      return fmt::format("{}({}, {}, {}, {}, {}, {})", call("de_juliabulb"), p, r(0), int(q[1]), bulb_estimator_radius(n, lit),
                         radius, c);
    }
    case Kind::Mandelbox:
      return fmt::format("{}({}, {})",
                         call(ir::DeMethod(int(q[12])) == ir::DeMethod::Jacobian ? "de_mandelbox_jacobian" : "de_mandelbox"), p,
                         orbit_args(n, lit));
    case Kind::QuaternionJulia: {
      double cn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      return fmt::format("{}({}, {}, {})", call("de_quaternion_julia"), p, orbit_args(n, lit),
                         lit.real(ir::julia_set_radius(q[4], cn)));
    }
    case Kind::Menger: return fmt::format("{}({}, {})", call("de_menger"), p, orbit_args(n, lit));
    case Kind::Sierpinski: return fmt::format("{}({}, {})", call("de_sierpinski"), p, orbit_args(n, lit));
    case Kind::Kifs: return fmt::format("{}({}, {})", call("de_kifs"), p, orbit_args(n, lit));
    case Kind::Hybrid: return hybrid(n, p, lit, w, used);
    case Kind::Formula:  // a chain of steps: compiler/src/formula/
      return formula::emit_chain(formula::chain(size_t(q[0])), p, lit, w, used, formula::Orbit::Distance);
    default: return "";
  }
}

namespace {

// The hybrid's orbit trap and smooth iteration count, written inline like its
// estimator: the same step pattern, the trap (smallest |coordinate|) and the
// steps taken; the fraction past the escape radius follows the growth law of
// the step that escaped (a power for a Mandelbulb step, linear for a box).
std::string hybrid_trap(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                        std::set<std::string>& used, bool iteration, const std::string& measure) {
  const HybridOrbit h = hybrid_orbit(n, lit);
  const std::string& escape = h.escape;
  std::string out = fmt::format("htrap{}", w.fresh());
  w.line(fmt::format("real {};  // hybrid orbit {}", out, iteration ? "smooth iteration count" : "trap"));
  w.open("{");
  w.line(fmt::format("vec3 z = {};", p));
  w.line("real dr = 1.0f, trap = 1e10f, n = 0.0f, growth = 2.0f, power_law = 0.0f;");
  w.line("real r = v3_length(z);");
  w.line(fmt::format("mask alive = r < {};", escape));
  w.open(fmt::format("for (int i = 0; i < {} && M_ANY(alive); ++i) {{", h.iterations));
  w.line(fmt::format("const int k = i % {};", h.period));
  w.line("vec3 z_next;");
  w.line("real g, law;");
  hybrid_steps(n, p, lit, w, used, "dr", true);
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
    w.line(fmt::format("{} = SEL((real)(1.0f), (n - frac) / {}, r >= {});", out, lit.real(double(h.iterations)), escape));
  } else {
    w.line(fmt::format("{} = trap;", out));
  }
  w.close("}");
  return out;
}

}  // namespace

std::string emit_fractal_trap(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used, OrbitValue value, std::optional<size_t> shape) {
  const auto& q = n.params;
  auto r = [&](size_t i) { return param(n, i, lit); };
  if (value == OrbitValue::Escape) {  // folding fractals never escape, and a hybrid reports its budget
    if (n.kind == Kind::Menger || n.kind == Kind::Sierpinski || n.kind == Kind::Hybrid) return lit.typed(q[0]);
    if (n.kind == Kind::Kifs) return lit.typed(q[5]);
  }
  if (n.kind == Kind::Formula)
    return formula::emit_chain(formula::chain(size_t(q[0])), p, lit, w, used,
                               value == OrbitValue::Escape   ? formula::Orbit::Escape
                               : value == OrbitValue::Smooth ? formula::Orbit::Smooth
                                                             : formula::Orbit::Trap,
                               shape ? trap_measure_call(*shape, "z", used) : "");
  if (n.kind == Kind::Hybrid)
    return hybrid_trap(n, p, lit, w, used, value == OrbitValue::Smooth,
                       shape ? trap_measure_call(*shape, "z", used) : "fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))");
  std::string fn, args;
  switch (n.kind) {
    case Kind::Mandelbulb:
    case Kind::Juliabulb: {
      const bool julia = n.kind == Kind::Juliabulb;
      const std::string c = julia ? lit.vec3({q[3], q[4], q[5]}) : "v3_splat(0.0f)";
      // Trig-free like the distance; the iterations AOV keeps the trig orbit,
      // whose rounding (and so escape step) it has always had.
      if (integer_power(q[0]) && !n.animation(0) && value != OrbitValue::Escape) {
        fn = "trap_mandelbulb_int";
        args = fmt::format("{}, {}, {}, {}, {}, {}", p, int(q[0]), int(q[1]), r(2), int(julia), c);
      } else {
        fn = "trap_mandelbulb";
        args = fmt::format("{}, {}, {}, {}, {}, {}", p, r(0), int(q[1]), r(2), int(julia), c);
      }
      break;
    }
    case Kind::Mandelbox: fn = "trap_mandelbox"; break;
    case Kind::QuaternionJulia: fn = "trap_quaternion_julia"; break;
    case Kind::Menger: fn = "trap_menger"; break;
    case Kind::Sierpinski: fn = "trap_sierpinski"; break;
    case Kind::Kifs: fn = "trap_kifs"; break;
    default: return "";
  }
  if (args.empty()) args = fmt::format("{}, {}", p, orbit_args(n, lit));
  if (shape) fn = shaped_trap_fn(fn, *shape, used);  // a copy with the material's trap shape
  else used.insert(fn);
  // One orbit gives every value; the caller picks one. Only escape-time
  // orbits have an escape iteration (the others returned theirs above).
  const bool escapes = n.kind == Kind::Mandelbulb || n.kind == Kind::Juliabulb || n.kind == Kind::Mandelbox ||
                       n.kind == Kind::QuaternionJulia;
  std::string t = fmt::format("otrap{}", w.fresh()), it = fmt::format("oiter{}", w.fresh());
  std::string count = escapes ? fmt::format("ocount{}", w.fresh()) : "";
  w.line(fmt::format("real {};", it));
  if (escapes) w.line(fmt::format("real {};", count));
  w.line(fmt::format("real {} = {}({}, &{}{});", t, fn, args, it, escapes ? ", &" + count : ""));
  return value == OrbitValue::Escape ? count : value == OrbitValue::Smooth ? it : t;
}

}  // namespace sdfc::codegen::detail
