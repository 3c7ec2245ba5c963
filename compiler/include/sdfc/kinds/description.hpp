#pragma once
// One description per node kind (compiler/src/kinds/, one file per kind or
// small family): its YAML form, its parameters by name, its properties, its
// stdlib call, its double-precision distance and an example. The passes,
// the emitter and the reference look a kind up here instead of switching
// over Kind. A description file starts with its SDFC_KIND line, the kind's
// row of the one kind table (compiler/kinds.cmake collects them):
//   SDFC_KIND(Enum, id, "printed name", Category, arity, "param names", "stdlib function")
#include <array>
#include <cstddef>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sdfc/ir/graph.hpp"
#include "sdfc/kinds/param_doc.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::kinds {

class Lowering;  // sdfc/kinds/lowering.hpp
struct Emitter;  // compiler/src/kinds/fractal.hpp: a fractal's node, point and code writer
class Walker;    // compiler/src/kinds/walker.hpp: the scene walker a node with children writes into
struct Carried;  // what the walker carries up from a node (distance, material, record)
class DualWalker;  // compiler/src/kinds/walker.hpp: the walker of render.normals: dual
struct Dual;     // a node's distance and gradient there
struct Folding;  // sdfc/kinds/folding.hpp: a node being rebuilt by fold_constants
using V3 = std::array<double, 3>;

// Proves the generated table saw this file's SDFC_KIND line.
#define SDFC_KIND(e, id, name, cat, arity, params, fn) \
  static_assert(static_cast<int>(::sdfc::ir::Kind::e) == (id), "kind table out of date: " #e);

// A kind's parameters as a struct of named doubles and V3s, in the order
// of Node::params: view<P>(n) reads them, params_of(p) writes them.
template <class P>
P view(const std::vector<double>& params) {
  static_assert(std::is_trivially_copyable_v<P> && sizeof(P) % sizeof(double) == 0);
  P p{};
  std::memcpy(&p, params.data(), std::min(sizeof(P), params.size() * sizeof(double)));
  return p;
}
template <class P>
P view(const ir::Node& n) { return view<P>(n.params); }
template <class P>
std::vector<double> params_of(const P& p) {
  std::vector<double> v(sizeof(P) / sizeof(double));
  std::memcpy(v.data(), &p, sizeof(P));
  return v;
}
template <class P>
constexpr size_t count_of() { return sizeof(P) / sizeof(double); }
// The index in Node::params of a field of P (for animated parameters, whose
// expression is kept by index): SDFC_AT(MandelbulbP, power).
#define SDFC_AT(P, field) (offsetof(P, field) / sizeof(double))

struct Description {
  ir::Kind kind;
  std::string_view yaml;     // the key a scene writes
  // One geometry node in YAML flow style: the tests render it, docs show it.
  std::string_view example = {};
  size_t param_count;        // count_of<P>(): checked against the table row
  // Reads the node's body (a map) and makes its node; kNoNode after an error.
  ir::NodeId (*lower)(Lowering&) = nullptr;
  // Bounds, class, Lipschitz constant and cost (infer_properties).
  ir::Props (*props)(const ir::Node&) = nullptr;
  // The stdlib call's arguments after the point, by parameter name from the
  // table row; "a" stands for ax, ay, az (a vec3). The function is the row's.
  std::string_view call_args = {};
  // The distance in double (the reference evaluator, the tests' oracle).
  double (*distance)(const ir::Node&, const V3& p) = nullptr;
  bool dual_normals = false;  // render.normals: dual differentiates it
  // The stdlib function giving distance and gradient (same arguments, then
  // the gradient's address); empty when there is none.
  std::string_view gradient_function = {};

  // ---- Fractals (Category::Fractal): estimators with an orbit. They write
  // their own code instead of the stdlib call of call_args; the registry's
  // start-up check requires emit, emit_orbit, orbit_colour and de_summary of
  // every fractal, and emit_dual of one that claims dual normals.
  // Writes any statements to the emitter and returns the distance expression.
  std::string (*emit)(Emitter&) = nullptr;
  // The orbit's value the emitter asks for (trap, smooth count or escape
  // step; see codegen's OrbitValue) at its point.
  std::string (*emit_orbit)(Emitter&) = nullptr;
  // render.normals: dual: writes any statements and returns the expression
  // of the estimate's gradient (its direction is the normal).
  std::string (*emit_dual)(Emitter&) = nullptr;
  // render.normals: dual on a kind whose support depends on the node (a
  // formula's steps): why this node cannot be differentiated, "" if it can.
  std::string (*dual_blocker)(const ir::Node&) = nullptr;
  // The double-precision orbit trap and smooth iteration count.
  reference::OrbitColour (*orbit_colour)(const ir::Node&, const V3& p, const ir::TrapShape& shape) = nullptr;
  // What `sdfc check` says of the estimator ("de: analytic, bound in practice ...").
  std::string (*de_summary)(const ir::Node&) = nullptr;
  // The step factor the node gets when its YAML gives none; null: 1.
  double (*step_factor)(const ir::Node&) = nullptr;
  // passes/fractal_bounds tightens the worst-case box by searching with the
  // estimator, believing this share of it (0: no search), with
  // bounds_distance instead of distance where that one overshoots.
  double bounds_trust = 0;
  double (*bounds_distance)(const ir::Node&, const V3& p) = nullptr;
  // An escape-time orbit: its estimate is good only outside the set, so
  // `sdfc mesh` takes the surface half a voxel out (a render stops at its
  // hit epsilon likewise).
  bool escape_time = false;
  // Its bounds are the cube around a ball (the set's radius): alone in a
  // scene, its rays are clipped to that ball too (passes/analyse).
  bool ball_bounds = false;
  // ---- end of the fractal members ----

  // ---- Kinds with children (domain operations, transforms, combinators;
  // kinds::operations(), not all()): they work on their children's results.
  // Written by the front end's modifiers and combinators, so they need no
  // lower, props, distance or stdlib call; the registry requires these three.
  // Bounds, class, L and cost from the children's: kid(i) is child i's props
  // as this node sees them (a corrected child is a bound with L = 1).
  ir::Props (*child_props)(const ir::Graph&, const ir::Node&, const std::function<ir::Props(size_t)>& kid) = nullptr;
  // The double-precision sample, evaluating the children with reference::evaluate.
  reference::Sample (*evaluate)(const ir::Graph&, const ir::Node&, const V3& p) = nullptr;
  // Its statements in the scene walker, which evaluates the children in
  // whatever the function being written carries (distance, material, trap,
  // material record); returns the node's value.
  Carried (*walk)(Walker&, const ir::Node&, const std::string& p) = nullptr;
  // A smooth combinator whose children's materials mix by their share of the
  // blended distance: its op_weight_* function; null or empty: none (the
  // nearer child's material, or the first's).
  std::string_view (*weight)(const ir::Node&) = nullptr;
  // render.normals: dual (dual_normals true): its distance and gradient,
  // from its children's.
  Dual (*walk_dual)(DualWalker&, const ir::Node&, const std::string& p) = nullptr;
  // fold_constants: the node made simpler (an identity dropped, nested ones
  // merged), or kNoNode to keep it as it is.
  ir::NodeId (*fold)(const Folding&) = nullptr;
  // camera.fit: where its bounds are unbounded, the union of its children's
  // finite parts frames it (a union of a fractal and a floor plane frames
  // the fractal).
  bool fit_children = false;
  // ---- end of the members of kinds with children ----

  // What the node is, in one line for the docs ("exact", "a bound", ...).
  std::string_view summary = {};
  // How a scene writes it, when that is not `yaml: {...}` (a modifier such
  // as `translate: [x, y, z]`, or several keys lowering to this kind).
  std::string_view written_as = {};
  // Its parameters for the docs, in the order a scene usually writes them.
  std::span<const ParamDoc> docs = {};
  // What `sdfc check` prints under the node (a formula's chain and its
  // estimator); null: nothing more than its class.
  std::string (*explain)(const ir::Node&) = nullptr;
};

}  // namespace sdfc::kinds
