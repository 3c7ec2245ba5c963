// Symbolic partial derivatives, for bounding gradients with intervals.
#include "functions.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::expr {

namespace {

ExprPtr make(Op op, std::vector<ExprPtr> args, double v = 0, std::string name = {}) {
  auto e = std::make_shared<Expr>();
  e->op = op;
  e->args = std::move(args);
  e->value = v;
  e->name = std::move(name);
  return e;
}
ExprPtr num(double v) { return make(Op::Number, {}, v); }
ExprPtr add(ExprPtr a, ExprPtr b) { return make(Op::Add, {std::move(a), std::move(b)}); }
ExprPtr sub(ExprPtr a, ExprPtr b) { return make(Op::Sub, {std::move(a), std::move(b)}); }
ExprPtr mul(ExprPtr a, ExprPtr b) { return make(Op::Mul, {std::move(a), std::move(b)}); }
ExprPtr dvd(ExprPtr a, ExprPtr b) { return make(Op::Div, {std::move(a), std::move(b)}); }
ExprPtr neg(ExprPtr a) { return make(Op::Neg, {std::move(a)}); }
ExprPtr pw(ExprPtr a, ExprPtr b) { return make(Op::Pow, {std::move(a), std::move(b)}); }
ExprPtr call(const char* f, std::vector<ExprPtr> args) { return make(Op::Call, std::move(args), 0, f); }

ExprPtr d(const ExprPtr& e, std::string_view v);

ExprPtr d_call(const ExprPtr& e, std::string_view v) {
  const auto& a = e->args;
  const std::string& f = e->name;
  ExprPtr u = a[0], du = d(u, v);
  if (f == "sin") return mul(call("cos", {u}), du);
  if (f == "cos") return neg(mul(call("sin", {u}), du));
  if (f == "tan") return mul(add(num(1), pw(e, num(2))), du);
  if (f == "exp") return mul(e, du);
  if (f == "log") return dvd(du, u);
  if (f == "sqrt") return dvd(du, mul(num(2), e));
  if (f == "abs") return mul(call("sgn", {u}), du);
  if (f == "sgn") return num(0);
  if (f == "min" || f == "max" || f == "hull") return call("hull", {du, d(a[1], v)});
  if (f == "clamp") return call("hull", {du, call("hull", {d(a[1], v), d(a[2], v)})});
  if (f == "mix") {  // a + (b - a) t
    ExprPtr da = du, db = d(a[1], v), dt = d(a[2], v);
    return add(add(da, mul(sub(db, da), a[2])), mul(sub(a[1], u), dt));
  }
  if (f == "smoothstep") {  // s(t) = t^2 (3 - 2t), t = clamp((x - e0) / (e1 - e0), 0, 1)
    ExprPtr e0 = a[0], e1 = a[1], x = a[2];
    ExprPtr w = sub(e1, e0);
    ExprPtr t = call("clamp", {dvd(sub(x, e0), w), num(0), num(1)});
    ExprPtr ds = mul(mul(num(6), t), sub(num(1), t));
    ExprPtr dt = dvd(sub(mul(sub(d(x, v), d(e0, v)), w), mul(sub(x, e0), sub(d(e1, v), d(e0, v)))), mul(w, w));
    return mul(ds, dt);
  }
  return call("hull", {num(0), num(0)});  // unreachable: every function has a rule above
}

ExprPtr d(const ExprPtr& e, std::string_view v) {
  const auto& a = e->args;
  switch (e->op) {
    case Op::Number:
    case Op::Slot: return num(0);
    case Op::Var: return num(e->name == v ? 1 : 0);
    case Op::Neg: return neg(d(a[0], v));
    case Op::Add: return add(d(a[0], v), d(a[1], v));
    case Op::Sub: return sub(d(a[0], v), d(a[1], v));
    case Op::Mul: return add(mul(d(a[0], v), a[1]), mul(a[0], d(a[1], v)));
    case Op::Div: return dvd(sub(mul(d(a[0], v), a[1]), mul(a[0], d(a[1], v))), mul(a[1], a[1]));
    case Op::Pow:
      if (is_constant(a[1])) return mul(mul(a[1], pw(a[0], sub(a[1], num(1)))), d(a[0], v));
      // u^w (w' log u + w u'/u)
      return mul(e, add(mul(d(a[1], v), call("log", {a[0]})), dvd(mul(a[1], d(a[0], v)), a[0])));
    case Op::Call: return d_call(e, v);
  }
  return num(0);
}

}  // namespace

ExprPtr derivative(const ExprPtr& e, std::string_view var) { return fold(d(e, var)); }

}  // namespace sdfc::expr
