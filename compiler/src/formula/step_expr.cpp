// expr: new components of z written in the expression language, as
// functions of x, y, z (the current z) and cx, cy, cz (c). Its derivative is
// the expressions' symbolic partials: the Jacobian takes E J + E_c dc.
#include <fmt/format.h>

#include "../codegen/code_writer.hpp"
#include "../codegen/kernel_text.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

const char* kZ[3] = {"x", "y", "z"};
const char* kC[3] = {"cx", "cy", "cz"};

// Component i of the new z: its expression, or z_i kept.
expr::ExprPtr component(const Step& st, int i) {
  static const expr::ExprPtr vars[3] = {
      std::make_shared<const expr::Expr>(expr::Expr{expr::Op::Var, 0, "x", {}, 0}),
      std::make_shared<const expr::Expr>(expr::Expr{expr::Op::Var, 0, "y", {}, 0}),
      std::make_shared<const expr::Expr>(expr::Expr{expr::Op::Var, 0, "z", {}, 0})};
  return st.e[size_t(i)] ? st.e[size_t(i)] : vars[i];
}

// Never conformal in general; a chain with one takes the Jacobian.
bool expr_conformal(const Step&) { return false; }

void expr_emit(const Step& st, EmitState& s) {
  auto var = [](std::string_view v) -> std::string {
    for (int i = 0; i < 3; ++i) {
      if (v == kZ[i]) return std::string("ez.") + kZ[i];
      if (v == kC[i]) return std::string("c.") + kZ[i];
    }
    return "time";
  };
  auto lit = [&](double x) { return s.lit.typed(x); };
  s.w.open("{  // expr");
  s.w.line("const vec3 ez = z;");
  for (int i = 0; i < 3; ++i)
    if (st.e[size_t(i)])
      s.w.line(fmt::format("z.{} = {};  // {}", kZ[i], expr::to_opencl(st.e[size_t(i)], var, lit),
                           codegen::kernel_text(expr::to_string(st.e[size_t(i)]), 200)));
  if (s.jacobian) {
    // new column k = sum_j dF/dz_j old_col_k[j] + dF/dc_k id
    s.w.line("const vec3 oa = ja, ob = jb, oc = jc;");
    const char* cols[3] = {"a", "b", "c"};
    for (int k = 0; k < 3; ++k) {
      std::string row[3];
      for (int i = 0; i < 3; ++i) {
        std::string sum;
        for (int j = 0; j < 3; ++j) {
          expr::ExprPtr d = expr::fold(expr::derivative(component(st, i), kZ[j]));
          if (expr::is_constant(d) && expr::evaluate(d, {}) == 0) continue;
          sum += fmt::format("{}({}) * o{}.{}", sum.empty() ? "" : " + ", expr::to_opencl(d, var, lit), cols[k], kZ[j]);
        }
        expr::ExprPtr dc = expr::fold(expr::derivative(component(st, i), kC[k]));
        if (!(expr::is_constant(dc) && expr::evaluate(dc, {}) == 0))
          sum += fmt::format("{}({}) * id", sum.empty() ? "" : " + ", expr::to_opencl(dc, var, lit));
        row[i] = sum.empty() ? lit(0) : sum;
      }
      s.w.line(fmt::format("j{} = v3({}, {}, {});", cols[k], row[0], row[1], row[2]));
    }
  }
  s.w.close("}");
}

void expr_eval(const Step& st, RefState& s) {
  expr::Env env{{"x", s.z[0]}, {"y", s.z[1]}, {"z", s.z[2]}, {"cx", s.c[0]}, {"cy", s.c[1]}, {"cz", s.c[2]}, {"time", 0}};
  V3 next;
  for (int i = 0; i < 3; ++i) next[size_t(i)] = expr::evaluate(component(st, i), env);
  std::array<V3, 3> j{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      double v = 0;
      for (int m = 0; m < 3; ++m) v += expr::evaluate(expr::derivative(component(st, i), kZ[m]), env) * s.j[size_t(k)][size_t(m)];
      if (s.mandel) v += expr::evaluate(expr::derivative(component(st, i), kC[k]), env);
      j[size_t(k)][size_t(i)] = v;
    }
  s.j = j;
  s.z = next;
}

}  // namespace

// Whether every partial of the step is a constant: a linear map, no power.
bool expr_is_linear(const Step& st) {
  for (int i = 0; i < 3; ++i)
    for (const char* v : kZ)
      if (!expr::is_constant(expr::fold(expr::derivative(component(st, i), v)))) return false;
  return true;
}

extern const StepDef kExpr{"expr", {}, expr_conformal, true, expr_emit, expr_eval,
                           "new x, y, z as expressions of x, y, z and cx, cy, cz"};

}  // namespace sdfc::formula
