// expr: new components of z written in the expression language, as
// functions of x, y, z (the current z) and cx, cy, cz (c). Its derivative is
// the expressions' symbolic partials: the Jacobian takes E J + E_c dc.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "../codegen/code_writer.hpp"
#include "../codegen/kernel_text.hpp"
#include "sdfc/expr/tape.hpp"
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

}  // namespace

void differentiate(Step& st) {
  st.partials.clear();
  for (const char* const* vars : {kZ, kC})
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) st.partials.push_back(expr::fold(expr::derivative(component(st, i), vars[j])));
  std::vector<expr::ExprPtr> roots{component(st, 0), component(st, 1), component(st, 2)};
  roots.insert(roots.end(), st.partials.begin(), st.partials.end());
  st.tape = std::make_shared<const expr::Tape>(roots, std::vector<std::string>{"x", "y", "z", "cx", "cy", "cz", "time"});
  // Whether the partials d(new z)/dz are constants: the folded partials of
  // 2*x still hold 0*x (folding it away would be wrong for infinite x), so
  // their values at a few points are compared instead.
  const double pts[3][7] = {{0.3, -0.7, 1.1, 0.2, 0.5, -0.4, 0}, {-1.3, 0.4, 0.9, -0.6, 0.1, 0.8, 0}, {2.1, 1.7, -0.5, 0.3, -0.9, 1.2, 0}};
  double v[3][21];
  for (int k = 0; k < 3; ++k) st.tape->run(pts[k], v[k]);
  st.linear = true;
  for (size_t i = 3; i < 12; ++i)
    for (int k = 1; k < 3; ++k)
      st.linear = st.linear && std::fabs(v[k][i] - v[0][i]) <= 1e-12 * std::max(1.0, std::fabs(v[0][i]));
}

namespace {

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
          const expr::ExprPtr& d = st.partials[size_t(3 * i + j)];
          if (expr::is_constant(d) && expr::evaluate(d, {}) == 0) continue;
          sum += fmt::format("{}({}) * o{}.{}", sum.empty() ? "" : " + ", expr::to_opencl(d, var, lit), cols[k], kZ[j]);
        }
        const expr::ExprPtr& dc = st.partials[size_t(9 + 3 * i + k)];
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
  const double at[7] = {s.z[0], s.z[1], s.z[2], s.c[0], s.c[1], s.c[2], 0};
  double v[21];  // the new x, y, z, then the partials (differentiate)
  st.tape->run(at, v);
  const double* d = v + 3;
  std::array<V3, 3> j{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      double sum = 0;
      for (int m = 0; m < 3; ++m) sum += d[3 * i + m] * s.j[size_t(k)][size_t(m)];
      if (s.mandel) sum += d[9 + 3 * i + k];
      j[size_t(k)][size_t(i)] = sum;
    }
  s.j = j;
  s.z = {v[0], v[1], v[2]};
}

}  // namespace

extern const StepDef kExpr{"expr", {}, expr_conformal, true, expr_emit, expr_eval,
                           "new x, y, z as expressions of x, y, z and cx, cy, cz", false, keeps_dr};

}  // namespace sdfc::formula
