#include "rotation_matrix.hpp"

#include <cmath>
#include <numbers>

#include "sdfc/expr/expr.hpp"
#include "sdfc/ir/fractal_math.hpp"

namespace sdfc::frontend {

namespace {

using Mat3 = std::array<double, 9>;

Mat3 mul(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i * 3 + j] += a[i * 3 + k] * b[k * 3 + j];
  return r;
}

// Rodrigues' formula (ir::axis_rotation) for an animated angle: each entry
// an expression of time.
using MatE = std::array<expr::ExprPtr, 9>;
using expr::Op;

expr::ExprPtr as_expr(const Param& p) { return p.anim ? p.anim : expr::number(p.value); }

bool is_zero(const expr::ExprPtr& e) { return e->op == Op::Number && e->value == 0; }

// sum + k * term, leaving out zero terms (so the kernel holds no 0 * sin(...)).
expr::ExprPtr add_term(expr::ExprPtr sum, expr::ExprPtr k, expr::ExprPtr term) {
  if (is_zero(k) || is_zero(term)) return sum;
  expr::ExprPtr prod = k->op == Op::Number && k->value == 1 ? term : expr::binary(Op::Mul, std::move(k), std::move(term));
  return is_zero(sum) ? prod : expr::binary(Op::Add, std::move(sum), std::move(prod));
}

MatE axis_angle(const Vec3d& a, const Param& deg) {
  auto num = expr::number;
  expr::ExprPtr t = expr::binary(Op::Mul, as_expr(deg), num(std::numbers::pi / 180.0));
  expr::ExprPtr c = expr::call("cos", {t}), s = expr::call("sin", {t});
  expr::ExprPtr C = expr::binary(Op::Sub, num(1), c);
  double x = a[0], y = a[1], z = a[2];
  auto e = [&](double cc, double ss, double k) {
    return add_term(add_term(add_term(num(0), num(cc), c), num(ss), s), num(k), C);
  };
  return {e(1, 0, x * x), e(0, -z, x * y), e(0, y, x * z),
          e(0, z, y * x), e(1, 0, y * y), e(0, -x, y * z),
          e(0, -y, z * x), e(0, x, z * y), e(1, 0, z * z)};
}

MatE mul(const MatE& a, const MatE& b) {
  MatE r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      expr::ExprPtr sum = expr::number(0);
      for (int k = 0; k < 3; ++k) sum = add_term(sum, a[i * 3 + k], b[k * 3 + j]);
      r[i * 3 + j] = sum;
    }
  return r;
}

// A matrix entry as a parameter: a rotation's entries lie in [-1, 1].
Param entry(const expr::ExprPtr& e) {
  if (expr::is_constant(e)) return expr::evaluate(e, {});
  Param p;
  p.anim = e;
  p.value = expr::evaluate(e, {{"time", 0.0}});
  p.lo = -1, p.hi = 1;
  return p;
}

}  // namespace

std::array<double, 9> rotation_matrix(const std::array<Vec3d, 3>& axes, const Param3& deg, int count) {
  Mat3 m = ir::axis_rotation(axes[0], deg[0].value);
  if (count == 3) m = mul(m, mul(ir::axis_rotation(axes[1], deg[1].value), ir::axis_rotation(axes[2], deg[2].value)));
  return m;
}

std::vector<Param> animated_rotation(const std::array<Vec3d, 3>& axes, const Param3& deg, int count) {
  MatE m = axis_angle(axes[0], deg[0]);
  for (int i = 1; i < count; ++i) m = mul(m, axis_angle(axes[i], deg[i]));
  std::vector<Param> entries;
  for (const auto& e : m) entries.push_back(entry(e));
  return entries;
}

}  // namespace sdfc::frontend
