#include "sdfc/expr/tape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "functions.hpp"

namespace sdfc::expr {

Tape::Tape(const std::vector<ExprPtr>& roots, const std::vector<std::string>& vars) {
  for (const ExprPtr& r : roots) roots_.push_back(add(r, vars));
}

// Children first, so one pass in order evaluates every node after its
// arguments. A tree shared between roots is flattened once per use.
int Tape::add(const ExprPtr& e, const std::vector<std::string>& vars) {
  Node n{e->op};
  n.value = e->value;
  if (e->op == Op::Var) {
    const auto it = std::find(vars.begin(), vars.end(), e->name);
    if (it != vars.end()) {
      n.var = int(it - vars.begin());
    } else {
      unknown_.push_back(e->name);
      n.var = -int(unknown_.size());
    }
  }
  if (e->op == Op::Call) {
    n.fn = find_function(e->name);
    if (!n.fn) throw std::logic_error("expression function '" + e->name + "' is unknown");
    n.arity = int(std::min<size_t>(e->args.size(), 3));
  }
  for (size_t i = 0; i < e->args.size() && i < 3; ++i) n.args[i] = add(e->args[i], vars);
  nodes_.push_back(n);
  return int(nodes_.size()) - 1;
}

void Tape::run(const double* vars, double* out) const {
  thread_local std::vector<double> values;  // the reference render runs on several threads
  values.resize(nodes_.size());
  double* v = values.data();
  for (size_t i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    switch (n.op) {
      case Op::Number:
      case Op::Slot: v[i] = n.value; break;
      case Op::Var:
        if (n.var < 0) throw std::logic_error("expression variable '" + unknown_[size_t(-1 - n.var)] + "' has no value");
        v[i] = vars[n.var];
        break;
      case Op::Neg: v[i] = -v[n.args[0]]; break;
      case Op::Add: v[i] = v[n.args[0]] + v[n.args[1]]; break;
      case Op::Sub: v[i] = v[n.args[0]] - v[n.args[1]]; break;
      case Op::Mul: v[i] = v[n.args[0]] * v[n.args[1]]; break;
      case Op::Div: v[i] = v[n.args[0]] / v[n.args[1]]; break;
      case Op::Pow: v[i] = std::pow(v[n.args[0]], v[n.args[1]]); break;
      case Op::Call: {
        double a[3] = {0, 0, 0};
        for (int k = 0; k < n.arity; ++k) a[k] = v[n.args[k]];
        v[i] = n.fn->eval(a);
        break;
      }
    }
  }
  for (size_t k = 0; k < roots_.size(); ++k) out[k] = v[roots_[k]];
}

}  // namespace sdfc::expr
