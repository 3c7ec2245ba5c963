#pragma once
// A formula: a chain of steps applied to z every iteration, read from a
// scene's `formula:` node. The compiler classifies the steps, picks the
// distance estimator (plan.cpp), writes the orbit as straight-line OpenCL
// (emit_chain.cpp) and evaluates it in double for the tests (evaluate_chain.cpp).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "sdfc/expr/expr.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::formula {

struct StepDef;  // sdfc/formula/step.hpp

// Caps that keep a kernel and its compile time bounded.
inline constexpr int kMaxIterations = 1000;
inline constexpr int kMaxSteps = 64;     // after repeats are unrolled
inline constexpr int kMaxRepeat = 16;

struct Step {
  const StepDef* def = nullptr;
  std::vector<double> a;             // the step's numbers, in its def's order (vec3s as three)
  std::array<expr::ExprPtr, 3> e{};  // expr: the new x, y, z (null keeps the component)
  // expr: d(new z_i)/dz_j at 3i + j, then d(new z_i)/dc_j at 9 + 3i + j (folded)
  std::vector<expr::ExprPtr> partials;
  int from = 0;                      // runs on iterations from <= i < until
  int until = kMaxIterations;
  int period = 0;                    // > 0: from/until count iterations modulo period (a preset's cycle)
  SourceLoc loc;
};

// `de:` as written: auto picks from the chain.
// Kleinian: Mandelbulber's pseudo-Kleinian estimate
// max(rxy - kleinian_size, |rxy z.z| / r) / |dr| for chains that never escape.
enum class DeChoice { Auto, Linear, Log, Jacobian, Kleinian };

struct Chain {
  std::vector<Step> steps;  // repeats already unrolled
  int iterations = 12;
  double bailout = 100;
  bool julia = false;
  std::array<double, 3> c{0, 0, 0};  // julia's constant
  DeChoice de = DeChoice::Auto;
  int repeat_from = 0;  // iterations after the first start at this step
  double kleinian_size = 1;  // de: kleinian's cylinder radius
  double set_radius = 0;     // > 0: the set lies in this ball (far field and bounds), else in the bailout ball
  double bounds_trust = 0;   // > 0: the share of the estimate the bounds search believes, else the kind's (half)
  std::string preset;        // the preset it was expanded from, if any
};

// The estimator the compiler chose and why (`sdfc check` prints it).
struct Plan {
  bool jacobian = false;  // a running 3x3 Jacobian, else a scalar derivative
  bool log = false;       // 0.5 log(r) r / |dr|, else r / |dr|
  bool kleinian = false;  // the pseudo-Kleinian form (DeChoice::Kleinian)
  std::string why;
};
Plan plan(const Chain& c);

// One line per step ("box_fold limit 1"), then the estimator.
std::string describe(const Chain& c);

// Chains live in one process-wide table (a node holds the index): equal
// chains get one index. Thread-safe; entries are never removed.
size_t intern(Chain c);
const Chain& chain(size_t index);

}  // namespace sdfc::formula
