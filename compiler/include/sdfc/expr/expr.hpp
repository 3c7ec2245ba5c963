#pragma once
// The small expression language of scene values: "8 + 0.5*sin(time)",
// "0.05*sin(10*x)*sin(10*y)*sin(10*z)". Numbers, + - * / ^ (right-assoc),
// unary minus, parentheses, variables the caller allows (time; x, y, z for
// displacement) and the functions sin cos tan exp log sqrt abs min max
// clamp mix smoothstep. Parsed with locations (errors point at the column
// inside the string), folded where constant, evaluated on the CPU (double
// and interval arithmetic) and emitted as OpenCL C.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::expr {

// Slot: an unlocked scene value (sdfc/source/unlock.hpp), read from the frame
// block at run time; it holds the value it was built with and the range the
// compiler assumed for it. Only code makes one (no text parses to it).
enum class Op { Number, Var, Neg, Add, Sub, Mul, Div, Pow, Call, Slot };

struct Expr;
using ExprPtr = std::shared_ptr<const Expr>;

struct Expr {
  Op op = Op::Number;
  double value = 0;           // Number
  std::string name;           // Var name or Call function name
  std::vector<ExprPtr> args;  // operands / call arguments
  int offset = 0;             // 0-based offset of this node in the source string
  int slot = 0;               // Slot: its index among the unlocked values
  double lo = 0, hi = 0;      // Slot: the range every run-time value stays in
};

// Parses `text`. `at` is the location of the string's first character in the
// scene (so an error at offset k is reported at column at.column + k).
// `variables` are the names allowed. Throws SceneError naming unknown
// functions/variables, wrong argument counts and syntax errors.
ExprPtr parse(std::string_view text, const SourceLoc& at, const std::vector<std::string>& variables);

// Is `text` worth parsing as an expression (a string that is not a plain number)?
bool looks_like_expression(std::string_view text);

// Folds constant subexpressions (sin(0) + 2*3 -> 6).
ExprPtr fold(const ExprPtr& e);
bool is_constant(const ExprPtr& e);  // no variables at all
bool uses(const ExprPtr& e, std::string_view var);

using Env = std::map<std::string, double, std::less<>>;
double evaluate(const ExprPtr& e, const Env& vars);

// Interval arithmetic: a range that holds every value of e for variables in
// their ranges (conservative; may be wider than the true range).
struct Interval {
  double lo = 0, hi = 0;
  double magnitude() const;  // max |v| over the interval
};
using IntervalEnv = std::map<std::string, Interval, std::less<>>;
Interval evaluate_interval(const ExprPtr& e, const IntervalEnv& vars);

// Symbolic partial derivative (used to bound gradients with intervals).
ExprPtr derivative(const ExprPtr& e, std::string_view var);

// OpenCL C for e. `variable` maps a variable name to the kernel expression
// that holds it; `literal` formats a constant in the kernel's precision.
std::string to_opencl(const ExprPtr& e, const std::function<std::string(std::string_view)>& variable,
                      const std::function<std::string(double)>& literal);

// Canonical text (stable; used in IR printing and hash-consing keys).
std::string to_string(const ExprPtr& e);

// Building expressions in code: derived values of animated parameters
// (a box's half size from its size, a rotation matrix from its angle).
ExprPtr number(double v);
ExprPtr binary(Op op, ExprPtr a, ExprPtr b);  // Add, Sub, Mul, Div, Pow
ExprPtr negate(ExprPtr a);
ExprPtr call(std::string name, std::vector<ExprPtr> args);
// Unlocked value number `index`, now `value`, always within [lo, hi]. It
// evaluates to `value`, its interval is [lo, hi], and the kernel reads it as
// `unlocked[index]`.
ExprPtr slot(int index, double value, double lo, double hi);
// e with `var` replaced by `value`, folded (an animated value at one time).
ExprPtr substitute(const ExprPtr& e, std::string_view var, double value);

// Animated scene values are expressions of `time`, in seconds. The compiler
// checks them (ranges, bounds) for every time in [0, kMaxTime].
inline constexpr double kMaxTime = 1e6;

}  // namespace sdfc::expr
