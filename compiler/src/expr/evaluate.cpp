// Folding, point evaluation, canonical text and OpenCL emission.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "functions.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::expr {

bool is_constant(const ExprPtr& e);
double evaluate(const ExprPtr& e, const Env& vars);

namespace {

ExprPtr number(double v, int offset) {
  auto e = std::make_shared<Expr>();
  e->op = Op::Number;
  e->value = v;
  e->offset = offset;
  return e;
}

bool is_number(const ExprPtr& e, double v) { return e->op == Op::Number && e->value == v; }

// An integer exponent small enough to expand into multiplications.
bool small_integer(const ExprPtr& e, int& n) {
  if (!is_constant(e)) return false;
  double v = evaluate(e, {});
  if (v != std::floor(v) || std::fabs(v) > 8) return false;
  n = static_cast<int>(v);
  return true;
}

}  // namespace

bool uses(const ExprPtr& e, std::string_view var) {
  if (e->op == Op::Var) return e->name == var;
  for (const auto& a : e->args)
    if (uses(a, var)) return true;
  return false;
}

bool is_constant(const ExprPtr& e) {
  if (e->op == Op::Var || e->op == Op::Slot) return false;
  for (const auto& a : e->args)
    if (!is_constant(a)) return false;
  return true;
}

double evaluate(const ExprPtr& e, const Env& vars) {
  auto arg = [&](size_t i) { return evaluate(e->args[i], vars); };
  switch (e->op) {
    case Op::Number:
    case Op::Slot: return e->value;
    case Op::Var: {
      auto it = vars.find(e->name);
      if (it == vars.end()) throw std::logic_error("expression variable '" + e->name + "' has no value");
      return it->second;
    }
    case Op::Neg: return -arg(0);
    case Op::Add: return arg(0) + arg(1);
    case Op::Sub: return arg(0) - arg(1);
    case Op::Mul: return arg(0) * arg(1);
    case Op::Div: return arg(0) / arg(1);
    case Op::Pow: return std::pow(arg(0), arg(1));
    case Op::Call: {
      double a[3] = {0, 0, 0};
      for (size_t i = 0; i < e->args.size() && i < 3; ++i) a[i] = arg(i);
      return find_function(e->name)->eval(a);
    }
  }
  return 0;
}

ExprPtr fold(const ExprPtr& e) {
  if (e->op == Op::Number || e->op == Op::Var || e->op == Op::Slot) return e;
  auto f = std::make_shared<Expr>(*e);
  for (auto& a : f->args) a = fold(a);
  if (is_constant(f)) return number(evaluate(f, {}), e->offset);
  const auto& a = f->args;
  switch (f->op) {
    case Op::Add:
      if (is_number(a[0], 0)) return a[1];
      if (is_number(a[1], 0)) return a[0];
      break;
    case Op::Sub:
      if (is_number(a[1], 0)) return a[0];
      break;
    case Op::Mul:
      if (is_number(a[0], 1)) return a[1];
      if (is_number(a[1], 1)) return a[0];
      break;
    case Op::Div:
    case Op::Pow:
      if (is_number(a[1], 1)) return a[0];
      break;
    default: break;
  }
  return f;
}

std::string to_string(const ExprPtr& e) {
  auto bin = [&](const char* op) { return "(" + to_string(e->args[0]) + " " + op + " " + to_string(e->args[1]) + ")"; };
  switch (e->op) {
    case Op::Number: return fmt::format("{}", e->value);
    case Op::Var: return e->name;
    case Op::Slot: return fmt::format("unlocked[{}]", e->slot);
    case Op::Neg: return "(-" + to_string(e->args[0]) + ")";
    case Op::Add: return bin("+");
    case Op::Sub: return bin("-");
    case Op::Mul: return bin("*");
    case Op::Div: return bin("/");
    case Op::Pow: return bin("^");
    case Op::Call: {
      std::string s = e->name + "(";
      for (size_t i = 0; i < e->args.size(); ++i) s += (i ? ", " : "") + to_string(e->args[i]);
      return s + ")";
    }
  }
  return "?";
}

std::string to_opencl(const ExprPtr& e, const std::function<std::string(std::string_view)>& variable,
                      const std::function<std::string(double)>& literal) {
  auto sub = [&](size_t i) { return to_opencl(e->args[i], variable, literal); };
  auto bin = [&](const char* op) { return "(" + sub(0) + " " + op + " " + sub(1) + ")"; };
  switch (e->op) {
    case Op::Number: return literal(e->value);
    case Op::Var: return variable(e->name);
    case Op::Slot: return fmt::format("((scalar)unlocked[{}])", e->slot);
    case Op::Neg: return "(-" + sub(0) + ")";
    case Op::Add: return bin("+");
    case Op::Sub: return bin("-");
    case Op::Mul: return bin("*");
    case Op::Div: return bin("/");
    case Op::Pow: {
      int n = 0;
      if (small_integer(e->args[1], n)) {
        // x^n by multiplication: exact, fast, and defined for negative x (pow is not).
        if (n == 0) return literal(1.0);
        std::string x = sub(0), prod = x;
        for (int i = 1; i < std::abs(n); ++i) prod += " * " + x;
        return n > 0 ? "(" + prod + ")" : "(" + literal(1.0) + " / (" + prod + "))";
      }
      return "pow(" + sub(0) + ", " + sub(1) + ")";
    }
    case Op::Call: {
      std::string s = std::string(find_function(e->name)->opencl) + "(";
      for (size_t i = 0; i < e->args.size(); ++i) s += (i ? ", " : "") + sub(i);
      return s + ")";
    }
  }
  return "?";
}

}  // namespace sdfc::expr
