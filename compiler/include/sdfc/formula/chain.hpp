#pragma once
// A formula: a chain of steps applied to z every iteration, read from a
// scene's `formula:` node. The compiler classifies the steps, picks the
// distance estimator (plan.cpp), writes the orbit as straight-line OpenCL
// (emit_chain.cpp) and evaluates it in double for the tests (evaluate_chain.cpp).
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sdfc/expr/expr.hpp"
#include "sdfc/expr/tape.hpp"
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
  std::shared_ptr<const expr::Tape> tape;  // expr: x, y, z, then the partials, at (x, y, z, cx, cy, cz, time)
  bool linear = false;                     // expr: every d(new z)/dz is a constant: a linear map, no power
  int from = 0;                      // runs on iterations from <= i < until
  int until = kMaxIterations;
  int period = 0;                    // > 0: from/until count iterations modulo period (a preset's cycle)
  SourceLoc loc;
};

// `de:` as written: auto picks from the chain.
// Kleinian: Mandelbulber's pseudo-Kleinian estimate
// max(rxy - kleinian_size, |rxy z.z| / r) / |dr| for chains that never escape.
// JosKleinian: Mandelbulber's Jos Leys Kleinian estimate
// min(y, jos_cap) / max(|dr|, jos_min_dr), y first folded to min(y, jos_height - y)
// when jos_height > 0 (its spheres).
enum class DeChoice { Auto, Linear, Log, Jacobian, Kleinian, JosKleinian };

// A built-in kind's node, as a scene would write it: a preset whose values
// the kind draws exactly renders with the kind's own hand-written code.
struct KindValue {
  std::string key;
  std::vector<double> numbers;  // one, or three for a vec3
  std::string word = {};        // a word instead (`de: jacobian`)
};
struct KindNode {
  std::string kind;  // the key scenes write (`mandelbox`)
  std::vector<KindValue> values;
};

struct Chain {
  std::vector<Step> steps;  // repeats already unrolled
  int iterations = 12;
  double bailout = 100;
  bool julia = false;
  std::array<double, 3> c{0, 0, 0};  // julia's constant
  // 4-D chains (a step uses w, the fourth component of z): julia's w, and
  // w's value at the start (the 3-D slice through the 4-D set).
  double cw = 0;
  double w_start = 0;
  DeChoice de = DeChoice::Auto;
  int repeat_from = 0;  // iterations after the first start at this step
  double kleinian_size = 1;  // de: kleinian's cylinder radius
  double jos_cap = 0.05, jos_min_dr = 1, jos_height = 0;  // de: jos_kleinian's numbers
  double set_radius = 0;     // > 0: the set lies in this ball (far field and bounds), else in the bailout ball
  double bounds_trust = 0;   // > 0: the share of the estimate the bounds search believes, else the kind's (half)
  std::string preset;        // the preset it was expanded from, if any
  std::optional<KindNode> builtin;  // set: the preset renders as this built-in node
};

// Whether z carries a fourth component w: some step uses it.
bool four_d(const Chain& c);

// The estimator the compiler chose and why (`sdfc check` prints it).
struct Plan {
  bool jacobian = false;  // a running 3x3 Jacobian, else a scalar derivative
  bool log = false;       // 0.5 log(r) r / |dr|, else r / |dr|
  bool kleinian = false;  // the pseudo-Kleinian form (DeChoice::Kleinian)
  bool jos_kleinian = false;  // the Jos Leys Kleinian form (DeChoice::JosKleinian)
  std::string why;
  // The step whose growth the estimate takes on trust ("expr (line 18)"):
  // the power step the log form assumes, else the first step that is not
  // conformal; empty when every step is conformal with a known factor.
  std::string leans_on;
};
Plan plan(const Chain& c);

// One line per step ("box_fold limit 1"), then the estimator.
std::string describe(const Chain& c);

// Chains live in one process-wide table (a node holds the index): equal
// chains get one index. Thread-safe; entries are never removed.
size_t intern(Chain c);
const Chain& chain(size_t index);

// Presets drawn by a built-in kind's code: the chain each stands for, by the
// source location of its node, so `sdfc check` can print it.
void note_builtin(const SourceLoc& at, size_t chain_index);
std::optional<size_t> builtin_chain_at(const SourceLoc& at);

}  // namespace sdfc::formula
