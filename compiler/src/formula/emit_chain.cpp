#include "sdfc/formula/emit.hpp"

#include <fmt/format.h>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

using codegen::detail::CodeWriter;

namespace {

// render.normals: dual: the step's rule on dr and gdr, before the step
// (z and the Jacobian as it receives them): gdr <- f gdr + dr J^T grad f.
void emit_step_dual(const Step& st, EmitState& s) {
  const DualFactor k = st.def->dual(st, s);
  if (k.f.empty() && k.adds.empty()) return;  // keeps dr
  const bool block = !k.temps.empty() || !k.grad_z.empty();
  if (block) s.w.open(fmt::format("{{  // {}: dr and its gradient", st.def->name));
  for (const std::string& t : k.temps) s.w.line(t);
  std::string grad;
  if (!k.grad_z.empty()) {
    s.w.line(fmt::format("const vec3 gz = {};", k.grad_z));
    grad = "v3(v3_dot(gz, ja), v3_dot(gz, jb), v3_dot(gz, jc))";
    if (!k.grad_w.empty()) grad = fmt::format("v3_add({}, v3_scale(jw, {}))", grad, k.grad_w);
  }
  if (!k.f.empty() && grad.empty()) s.w.line(fmt::format("gdr = v3_scale(gdr, {});", k.f));
  if (!grad.empty()) s.w.line(fmt::format("gdr = v3_add(v3_scale(gdr, {}), v3_scale({}, dr));", k.f, grad));
  if (!k.f.empty()) s.w.line(fmt::format("dr = {} * dr;", k.f));
  if (!k.adds.empty()) s.w.line(fmt::format("dr = dr + {};  // {}", k.adds, st.def->name));
  if (block) s.w.close();
}

// The steps of one iteration; `first`: the index the chain starts at.
void emit_steps(const Chain& c, EmitState& s, size_t first) {
  for (size_t k = first; k < c.steps.size(); ++k) {
    const Step& st = c.steps[k];
    const bool windowed = st.period > 0 || st.from > 0 || st.until < c.iterations;
    if (st.period > 0)
      s.w.open(fmt::format("if (i % {0} >= {1} && i % {0} < {2}) {{  // {3} on iterations {1} to {4} of every {0}", st.period,
                           st.from, st.until, st.def->name, st.until - 1));
    else if (windowed) s.w.open(fmt::format("if (i >= {} && i < {}) {{  // {} on iterations {} to {}", st.from, st.until,
                                       st.def->name, st.from, std::min(st.until, c.iterations) - 1));
    if (s.dual) emit_step_dual(st, s);
    st.def->emit(st, s);
    if (windowed) s.w.close();
  }
}

}  // namespace

std::string emit_chain(const Chain& c, const std::string& p, const codegen::detail::Literals& lit, CodeWriter& w,
                       std::set<std::string>& used, Orbit what, const std::string& measure) {
  const Plan pl = plan(c);
  // dual: the Jacobian (for grad z) and the scalar derivative with its gradient
  const bool dual = what == Orbit::Gradient;
  const bool jac = dual || (pl.jacobian && what == Orbit::Distance);
  const bool scalar = !jac || dual;
  const std::string out = fmt::format("fo{}", w.fresh());
  const std::string bail = lit.real(c.bailout);
  const bool wide = four_d(c);  // z carries w (a 3-D chain's text is unchanged)
  w.line(fmt::format("{} {};  // formula: {}", dual ? "vec3" : "real", out, dual ? "the gradient of " + pl.why : pl.why));
  w.open("{");
  w.line(fmt::format("vec3 z = {};", p));
  w.line(fmt::format("const vec3 c = {};", c.julia ? lit.vec3(c.c) : p));
  w.line(fmt::format("const real id = {};  // dc/dp", lit.typed(c.julia ? 0 : 1)));
  if (wide)
    w.line(fmt::format("real zw = {}; const real cw = {};  // z's and c's fourth components", lit.real(c.w_start),
                       lit.real(c.julia ? c.cw : 0)));
  if (jac) w.line("vec3 ja = v3(1.0f, 0.0f, 0.0f), jb = v3(0.0f, 1.0f, 0.0f), jc = v3(0.0f, 0.0f, 1.0f);");
  if (scalar) w.line(dual ? "real dr = 1.0f; vec3 gdr = v3_splat(0.0f);  // and its gradient" : "real dr = 1.0f;");
  if (jac && wide) w.line("vec3 jw = v3(0.0f, 0.0f, 0.0f);  // dw/dp");
  if (what != Orbit::Distance && !dual) w.line("real trap = 1e10f, n = 0.0f;");
  const char* length = wide ? "sqrt(v3_dot(z, z) + zw * zw)" : "v3_length(z)";
  w.line(fmt::format("real r = {};", length));
  w.line(fmt::format("mask alive = r < {};", bail));
  w.open(fmt::format("for (int i = 0; i < {} && M_ANY(alive); ++i) {{", c.iterations));
  w.line(jac ? "const vec3 z0 = z, ja0 = ja, jb0 = jb, jc0 = jc;" : "const vec3 z0 = z; const real dr0 = dr;");
  if (dual) w.line("const real dr0 = dr; const vec3 gdr0 = gdr;");
  if (wide) w.line(jac ? "const real zw0 = zw; const vec3 jw0 = jw;" : "const real zw0 = zw;");
  EmitState s{w, lit, used, jac};
  s.four_d = wide;
  s.dual = dual;
  if (c.repeat_from > 0) {
    w.open("if (i == 0) {");
    emit_steps(c, s, 0);
    w.close();
    w.open("else {");
    emit_steps(c, s, size_t(c.repeat_from));
    w.close();
  } else {
    emit_steps(c, s, 0);
  }
  w.line("z = v3_select(z0, z, alive);");
  if (jac) w.line("ja = v3_select(ja0, ja, alive); jb = v3_select(jb0, jb, alive); jc = v3_select(jc0, jc, alive);");
  if (scalar) w.line(dual ? "dr = SEL(dr0, dr, alive); gdr = v3_select(gdr0, gdr, alive);" : "dr = SEL(dr0, dr, alive);");
  if (wide) w.line(jac ? "zw = SEL(zw0, zw, alive); jw = v3_select(jw0, jw, alive);" : "zw = SEL(zw0, zw, alive);");
  if (what != Orbit::Distance && !dual) {
    w.line("n = SEL(n, n + 1.0f, alive);");
    w.line(fmt::format("trap = SEL(trap, fmin(trap, {}), alive);",
                       measure.empty() ? "fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))" : measure));
  }
  w.line(fmt::format("r = {};", length));
  w.line(fmt::format("alive = alive & (r < {});", bail));
  w.close("}");
  switch (what) {
    case Orbit::Distance: {
      std::string norm = jac ? wide ? "sqrt(v3_dot(ja, ja) + v3_dot(jb, jb) + v3_dot(jc, jc) + v3_dot(jw, jw))"
                                    : "sqrt(v3_dot(ja, ja) + v3_dot(jb, jb) + v3_dot(jc, jc))"
                             : "fabs(dr)";
      w.line(fmt::format("real dd = fmax({}, K(1e-30f));", norm));
      if (pl.kleinian)
        w.line(fmt::format("{{ real rxy = sqrt(z.x * z.x + z.y * z.y); {} = fmax(rxy - {}, fabs(rxy * z.z) / fmax(r, K(1e-20f))) / dd; }}",
                           out, lit.real(c.kleinian_size)));
      else if (pl.jos_kleinian)
        w.line(fmt::format("{{ real y = {}; {} = fmin(y, {}) / fmax(dd, {}); }}",
                           c.jos_height > 0 ? fmt::format("fmin(z.y, {} - z.y)", lit.real(c.jos_height)) : "z.y", out,
                           lit.real(c.jos_cap), lit.real(c.jos_min_dr)));
      else
        w.line(fmt::format("{} = {};", out, pl.log ? "0.5f * log(fmax(r, K(1e-20f))) * r / dd" : "r / dd"));
      w.line("// far field: the set lies inside the bailout ball, so beyond twice its radius the distance to");
      w.line("// the ball is a true bound");
      w.line(fmt::format("real r0 = v3_length({});", p));
      const double ball = c.set_radius > 0 ? c.set_radius : c.bailout;
      // jos_kleinian's set fills space: the chain keeps the part inside the bailout ball
      if (pl.jos_kleinian) w.line(fmt::format("{0} = fmax({0}, r0 - {1});", out, bail));
      w.line(fmt::format("{0} = SEL({0}, r0 - {1}, r0 > {2});", out, lit.real(ball), lit.real(2 * ball)));
      break;
    }
    case Orbit::Gradient: emit_estimate_gradient(c, pl, p, lit, w, out); break;
    case Orbit::Trap: w.line(fmt::format("{} = trap;", out)); break;
    case Orbit::Escape: w.line(fmt::format("{} = n;", out)); break;
    case Orbit::Smooth:
      // the fraction past the bailout, by the growth law the estimator assumes
      w.line(fmt::format("real rr = fmax(r, {0}), lb = log({0});", bail));
      w.line(pl.log ? "real frac = clamp(log(log(rr) / lb) / log(K(2.0f)), K(0.0f), K(1.0f));"
                    : "real frac = clamp(log(rr / " + bail + ") / log(K(2.0f)), K(0.0f), K(1.0f));");
      w.line(fmt::format("{} = SEL((real)(1.0f), (n - frac) / {}, r >= {});", out, lit.real(double(c.iterations)), bail));
      break;
  }
  w.close("}");
  return out;
}

}  // namespace sdfc::formula
