#pragma once
// What the fractal descriptions share: the emitter they write their
// estimator and orbit with, the lowering of `de:` and of a Mandelbox's
// scale and radii, and the double-precision orbit maths of their references.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "../codegen/code_writer.hpp"
#include "../codegen/fractal_emitter.hpp"
#include "sdfc/ir/fractal_math.hpp"
#include "sdfc/kinds/description.hpp"
#include "sdfc/kinds/lowering.hpp"

namespace sdfc::kinds {

// A fractal node being written at point p: its parameters as literals or
// (animated) expressions, the writer for statements and the stdlib
// functions used. `value` and `shape` say which orbit value emit_orbit is
// asked for and the material whose trap shape it takes.
struct Emitter {
  const ir::Node& n;
  const std::string& p;
  const codegen::detail::Literals& lit;
  codegen::detail::CodeWriter& w;
  std::set<std::string>& used;
  codegen::detail::OrbitValue value = codegen::detail::OrbitValue::Trap;
  std::optional<size_t> shape = std::nullopt;

  std::string param(size_t i) const { return codegen::detail::param(n, i, lit); }
  std::string real(double v) const { return lit.real(v); }
  std::string vec3(const V3& v) const { return lit.vec3(v); }
  // The stdlib function fn, recorded as used.
  std::string call(const char* fn) const {
    used.insert(fn);
    return fn;
  }
};

// The trap function fn(args, &iteration[, &escape count]) (copied with the
// material's trap shape when it has one); returns the variable holding the
// value asked for. Only escape-time orbits have an escape count.
std::string orbit_call(Emitter& e, std::string fn, const std::string& args, bool escapes);

// The escape radius a Mandelbulb's or Juliabulb's estimator iterates to
// (ir::bulb_estimator_radius), a literal or, for an animated power or
// bailout, an expression of them (`power` and `bailout` index Node::params).
std::string bulb_estimator_radius(const Emitter& e, size_t power, size_t bailout);
// A power the trig-free path can take: a whole number from 2 up.
inline bool integer_power(double power) { return power >= 2 && power == std::floor(power); }

// Lowering: `de: METHOD`, one of `methods` (the node's own); the error names
// them. A Mandelbox's scale (|scale| > 1) and its radii (min < fixed).
double de_method(frontend::ValueReader& r, const frontend::MapReader& m, std::string_view what,
                 std::initializer_list<ir::DeMethod> methods);
frontend::Param mandelbox_scale(frontend::MapReader& m, const std::string& what, frontend::ValueReader& r);
std::pair<double, double> mandelbox_radii(frontend::MapReader& m, const std::string& what, frontend::ValueReader& r);
// The `mandelbulb` key: a Mandelbulb, or with `julia:` a Juliabulb.
ir::NodeId lower_mandelbulb(Lowering& l);

// A fractal's properties: an estimate (a bound in practice, not provably)
// inside the cube of half-size `half`, at this cost.
inline ir::Props estimate(double half, double cost) {
  ir::Props p;
  p.known = true;
  p.bounds = ir::Box3::cube(half);
  p.cls = ir::DistanceClass::Estimate;
  p.cost = cost;
  return p;
}

// "de: analytic, bound in practice (not proven)" and its kin.
std::string de_words(ir::DeMethod method);

namespace orbit {

inline double len(const V3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The trap's measure of one orbit point (the trap is its smallest value).
double measure(const ir::TrapShape& t, const V3& z);
// n steps, |z| = r after them, escape radius R, growth g per step (a power
// for power_law, else a factor); 1 when the orbit never escaped.
double smooth_iteration(int n, double r, double R, double g, bool power_law, int iterations);

// White-Nylander power in spherical coordinates; r^(n-1) in *r_pow_n_minus_1.
V3 bulb_power(const V3& z, double n, double* r_pow_n_minus_1);
// The same power as the trap references compute it (r^n directly).
V3 bulb(const V3& z, double power);
// Box fold then sphere fold; returns the sphere fold's factor.
double box_sphere_fold(V3& z, double fl, double min_r, double fixed_r);
// |z| sorted descending (Menger), and the tetrahedral folds (Sierpinski).
void sort_descending(V3& z);
void tetra_folds(V3& z);
// The 3x3 row-major matrix m times v.
inline V3 apply(const std::array<double, 9>& m, const V3& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

}  // namespace orbit

}  // namespace sdfc::kinds
