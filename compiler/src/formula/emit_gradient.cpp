// render.normals: dual through a formula: the exact gradient of the
// estimate the march uses. The orbit carries the Jacobian of z (grad of each
// component of z is a row of it) and the scalar derivative dr with its
// gradient (each step's dual rule); the estimate is a function of z and dr,
// so its gradient is J^T (dF/dz) + (dF/d|dr|) grad |dr|.
#include <fmt/format.h>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/emit.hpp"

namespace sdfc::formula {

std::string dual_blocker(const Chain& c) {
  for (const Step& s : c.steps)
    if (!s.def->dual)
      return fmt::format("its step {} (line {}) has no dual-number rule for the scalar derivative", s.def->name, s.loc.line);
  const Plan pl = plan(c);
  if (!pl.jacobian) return "";
  if (c.de == DeChoice::Jacobian)
    return "its estimate (de: jacobian) divides by the running Jacobian's norm, whose gradient needs second derivatives";
  for (const Step& s : c.steps)
    if (!s.def->conformal(s))
      return fmt::format("its step {} (line {}) is not conformal, so the estimate divides by the running Jacobian's norm, "
                         "whose gradient needs second derivatives (de: linear or de: log would use the scalar derivative)",
                         s.def->name, s.loc.line);
  return "its estimate divides by the running Jacobian's norm";
}

void emit_estimate_gradient(const Chain& c, const Plan& pl, const std::string& p, const codegen::detail::Literals& lit,
                            codegen::detail::CodeWriter& w, const std::string& out) {
  const bool wide = four_d(c);
  // J^T v for a variable v: the gradient over the point of v . z, v held fixed
  auto jt = [](const char* v) { return fmt::format("v3(v3_dot({0}, ja), v3_dot({0}, jb), v3_dot({0}, jc))", v); };
  w.line("real dd = fmax(fabs(dr), K(1e-30f));");
  w.line("const vec3 gdd = v3_scale(gdr, sign(dr));  // grad |dr|");
  w.line("const real rr = fmax(r, K(1e-20f));");
  w.line(wide ? fmt::format("const vec3 gr = v3_scale(v3_add({}, v3_scale(jw, zw)), 1.0f / rr);  // grad r", jt("z"))
              : fmt::format("const vec3 gr = v3_scale({}, 1.0f / rr);  // grad r", jt("z")));
  // num / den and their gradients: the estimate is num / den
  w.line("real num, den = dd; vec3 gnum, gden = gdd;");
  if (pl.kleinian) {
    w.line("const real rxy = fmax(sqrt(z.x * z.x + z.y * z.y), K(1e-20f));");
    w.line("const vec3 zxy = v3(z.x, z.y, 0.0f);");
    w.line(fmt::format("const vec3 grxy = v3_scale({}, 1.0f / rxy);", jt("zxy")));
    w.line(fmt::format("const real a = rxy - {}, b = fabs(rxy * z.z) / rr;", lit.real(c.kleinian_size)));
    w.line("const vec3 gzz = v3(ja.z, jb.z, jc.z);");
    w.line("const vec3 gb = v3_sub(v3_scale(v3_add(v3_scale(grxy, fabs(z.z)), v3_scale(gzz, rxy * sign(z.z))), 1.0f / rr), "
           "v3_scale(gr, b / rr));");
    w.line("num = fmax(a, b); gnum = v3_select(gb, grxy, a > b);");
  } else if (pl.jos_kleinian) {
    w.line("const vec3 gy = v3(ja.y, jb.y, jc.y);");
    if (c.jos_height > 0) {
      w.line(fmt::format("const mask low = z.y < {} - z.y;", lit.real(c.jos_height)));
      w.line(fmt::format("const real y = SEL({} - z.y, z.y, low);", lit.real(c.jos_height)));
      w.line("const vec3 gyy = v3_select(v3_scale(gy, -1.0f), gy, low);");
    } else {
      w.line("const real y = z.y; const vec3 gyy = gy;");
    }
    const std::string cap = lit.real(c.jos_cap), min_dr = lit.real(c.jos_min_dr);
    w.line(fmt::format("num = fmin(y, {0}); gnum = v3_select(v3_splat(0.0f), gyy, y < {0});", cap));
    w.line(fmt::format("den = fmax(dd, {0}); gden = v3_select(v3_splat(0.0f), gdd, dd > {0});", min_dr));
  } else if (pl.log) {
    w.line("const real lr = 0.5f * log(rr);");
    w.line("num = lr * rr; gnum = v3_scale(gr, lr + 0.5f);");
  } else {
    w.line("num = rr; gnum = gr;");
  }
  w.line("real d = num / den;");
  w.line(fmt::format("{} = v3_sub(v3_scale(gnum, 1.0f / den), v3_scale(gden, num / (den * den)));", out));
  // the far field, as emit_chain's estimate
  w.line(fmt::format("const real r0 = v3_length({});", p));
  w.line(fmt::format("const vec3 g0 = v3_scale({}, 1.0f / fmax(r0, K(1e-20f)));", p));
  if (pl.jos_kleinian) {
    w.line(fmt::format("{0} = v3_select({0}, g0, r0 - {1} > d);", out, lit.real(c.bailout)));
    w.line(fmt::format("d = fmax(d, r0 - {});", lit.real(c.bailout)));
  }
  const double ball = c.set_radius > 0 ? c.set_radius : c.bailout;
  w.line(fmt::format("{0} = v3_select({0}, g0, r0 > {1});", out, lit.real(2 * ball)));
  w.line("(void)d;");
}

}  // namespace sdfc::formula
