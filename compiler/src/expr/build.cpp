// Expressions built in code, for values derived from animated parameters.
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

}  // namespace

ExprPtr number(double v) { return make(Op::Number, {}, v); }
ExprPtr binary(Op op, ExprPtr a, ExprPtr b) { return fold(make(op, {std::move(a), std::move(b)})); }
ExprPtr negate(ExprPtr a) { return fold(make(Op::Neg, {std::move(a)})); }
ExprPtr call(std::string name, std::vector<ExprPtr> args) { return fold(make(Op::Call, std::move(args), 0, std::move(name))); }

ExprPtr slot(int index, double value, double lo, double hi) {
  auto e = std::make_shared<Expr>();
  e->op = Op::Slot;
  e->slot = index, e->value = value, e->lo = lo, e->hi = hi;
  return e;
}

ExprPtr substitute(const ExprPtr& e, std::string_view var, double value) {
  if (e->op == Op::Var) return e->name == var ? number(value) : e;
  if (e->args.empty()) return e;
  auto f = std::make_shared<Expr>(*e);
  for (auto& a : f->args) a = substitute(a, var, value);
  return fold(f);
}

}  // namespace sdfc::expr
