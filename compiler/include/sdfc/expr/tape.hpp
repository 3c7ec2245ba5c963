#pragma once
// Expressions flattened for evaluation at many points: variables resolved
// to places in the caller's array and functions to their table entries
// once, instead of looked up by name at every node (expr::evaluate). The
// operations, their order and so the values are the tree walk's.
#include <string>
#include <vector>

#include "sdfc/expr/expr.hpp"

namespace sdfc::expr {

struct Function;  // functions.hpp

class Tape {
 public:
  // `roots` are evaluated together; `vars` name the values run() is given.
  Tape(const std::vector<ExprPtr>& roots, const std::vector<std::string>& vars);
  // out[k] = roots[k] at vars. A variable not in `vars` throws, as evaluate.
  void run(const double* vars, double* out) const;
  size_t size() const { return roots_.size(); }

 private:
  struct Node {
    Op op;
    double value = 0;               // Number, Slot
    int var = 0;                    // Var: index into vars, or -1 - index into unknown_
    int args[3] = {-1, -1, -1};     // earlier nodes
    int arity = 0;                  // Call
    const Function* fn = nullptr;   // Call
  };
  int add(const ExprPtr& e, const std::vector<std::string>& vars);
  std::vector<Node> nodes_;
  std::vector<int> roots_;
  std::vector<std::string> unknown_;  // variables not in vars, named in run()'s error
};

}  // namespace sdfc::expr
