// formula: a fractal written as a chain of steps (compiler/src/formula/);
// the node holds the chain's index in the chain table.
#include <fmt/format.h>

#include <stdexcept>

#include "../codegen/trap_shape_emitter.hpp"
#include "fractal.hpp"
#include "sdfc/formula/emit.hpp"
#include "sdfc/formula/evaluate.hpp"
#include "sdfc/formula/preset.hpp"
#include "sdfc/formula/read_chain.hpp"
#include "sdfc/kinds/formula_node.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/reference/evaluator.hpp"

SDFC_KIND(Formula, 55, "formula", Fractal, 0, "chain,iterations,bailout", "")

namespace sdfc::kinds {
namespace {

struct FormulaP {
  double chain, iterations, bailout;
};

// A preset the built-in kind draws exactly: the kind's node, lowered by the
// kind from a body written here; the chain it stands for is kept for `sdfc check`.
ir::NodeId lower_as_builtin(Lowering& l, formula::Chain c) {
  const formula::KindNode k = *c.builtin;
  const Description* d = kinds::find(std::string_view(k.kind));
  if (!d) throw std::logic_error("preset " + c.preset + ": no kind " + k.kind);
  auto scalar = [&](std::string text) {
    SourceValue v;
    v.kind = SourceValue::Kind::Scalar;
    v.loc = l.at();
    v.scalar = std::move(text);
    return v;
  };
  SourceValue body;
  body.kind = SourceValue::Kind::Map;
  body.loc = l.at();
  for (const formula::KindValue& kv : k.values) {
    SourceValue value = scalar(kv.word);
    if (kv.word.empty() && kv.numbers.size() == 1) value = scalar(fmt::format("{}", kv.numbers[0]));
    if (kv.word.empty() && kv.numbers.size() > 1) {
      value = SourceValue();
      value.kind = SourceValue::Kind::Sequence;
      value.loc = l.at();
      for (double x : kv.numbers) value.items.push_back(scalar(fmt::format("{}", x)));
    }
    body.entries.emplace_back(scalar(kv.key), std::move(value));
  }
  SourceValue key = l.key();
  key.scalar = k.kind;
  Lowering as_kind(*d, l.reader(), l.builder(), key, body);
  const ir::NodeId id = d->lower(as_kind);
  c.builtin.reset();
  formula::note_builtin(l.at(), formula::intern(std::move(c)));
  return id;
}

ir::NodeId lower(Lowering& l) {
  // `formula: {...}`, or a preset's own node (`pseudo_kleinian: {...}`)
  const formula::Preset* preset = formula::find_preset(l.key().scalar);
  std::optional<formula::Chain> c = preset ? formula::read_preset(l.reader(), *preset, l.body(), l.key())
                                           : formula::read_chain(l.reader(), l.body());
  if (!c) return ir::kNoNode;
  if (c->builtin) return lower_as_builtin(l, std::move(*c));
  FormulaP p{double(c->iterations), double(c->iterations), c->bailout};
  p.chain = double(formula::intern(std::move(*c)));
  return l.make(p);
}

ir::Props props(const ir::Node& n) {
  auto f = view<FormulaP>(n);
  const formula::Chain& c = formula::chain(size_t(f.chain));
  ir::Props p;
  p.known = true;
  // The set lies inside the bailout ball: an orbit from outside it stops at once.
  p.bounds = ir::Box3::cube(c.set_radius > 0 ? c.set_radius : c.bailout);
  // A quaternion Julia chain (q^n + c) lies inside the ball where |q|^n - |q| = |c|,
  // as the built-in julia: does (the bound search then starts from the same box).
  if (c.julia && c.steps.size() == 2 && c.steps[0].def->name == "quaternion" && c.steps[1].def->name == "add_c") {
    const double cn = std::sqrt(c.c[0] * c.c[0] + c.c[1] * c.c[1] + c.c[2] * c.c[2] + c.cw * c.cw);
    p.bounds = ir::Box3::cube(std::min(c.bailout, ir::julia_set_radius(c.steps[0].a[0], cn)));
  }
  p.cls = ir::DistanceClass::Estimate;
  p.lipschitz = 1;
  const double per_step = formula::plan(c).jacobian ? 40 : 12;
  p.cost = 20 + double(c.iterations) * (8 + per_step * double(c.steps.size()));
  return p;
}

double distance(const ir::Node& n, const V3& p) {
  return formula::evaluate(chain_of(n), p).distance;
}

std::string emit(Emitter& e) {
  return formula::emit_chain(chain_of(e.n), e.p, e.lit, e.w, e.used, formula::Orbit::Distance);
}

std::string emit_orbit(Emitter& e) {
  using codegen::detail::OrbitValue;
  const formula::Orbit what = e.value == OrbitValue::Escape   ? formula::Orbit::Escape
                              : e.value == OrbitValue::Smooth ? formula::Orbit::Smooth
                                                              : formula::Orbit::Trap;
  return formula::emit_chain(chain_of(e.n), e.p, e.lit, e.w, e.used, what,
                             e.shape ? codegen::detail::trap_measure_call(*e.shape, "z", e.used) : "");
}

std::string emit_dual(Emitter& e) {
  return formula::emit_chain(chain_of(e.n), e.p, e.lit, e.w, e.used, formula::Orbit::Gradient);
}

std::string dual_blocker(const ir::Node& n) { return formula::dual_blocker(chain_of(n)); }

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  const formula::Chain& c = chain_of(n);
  formula::OrbitResult o = formula::evaluate(c, p, [&](const V3& z) { return orbit::measure(shape, z); });
  return {o.trap, orbit::smooth_iteration(int(o.iterations), o.r, c.bailout, 2.0, formula::plan(c).log, c.iterations)};
}

// The bounds search believes the description's half of the estimate; a chain
// that trusts its estimate more (the hybrid preset, as the hybrid kind) scales it.
double bounds_distance(const ir::Node& n, const V3& p) {
  const formula::Chain& c = chain_of(n);
  const double d = formula::evaluate(c, p).distance;
  return c.bounds_trust > 0 ? d * c.bounds_trust / 0.5 : d;
}

// sdfc check prints the chain's own account (explain) instead.
std::string de_summary(const ir::Node&) { return ""; }

std::string explain(const ir::Node& n) { return formula::describe(formula::chain(size_t(view<FormulaP>(n).chain))); }

constexpr ParamDoc k_docs[] = {
    {"iterate", "list of steps", "", "1 to 64 steps", "the steps applied to z in order, every iteration (see docs/formulas.md)"},
    {"iterations", "integer", "12", "1 to 1000", "how many times the chain runs"},
    {"bailout", "number", "100", "1 to 1e6", "the orbit stops once |z| passes it; the fractal lies inside this ball"},
    {"julia", "vec3", "", "", "the constant add_c adds; without it c is the point (the Mandelbrot form)"},
    {"de", "one of auto|linear|log|jacobian", "auto", "", "the distance estimate; auto picks from the steps"},
    {"repeat_from", "integer", "0", "an index into iterate", "iterations after the first start at this step"},
};

}  // namespace

const formula::Chain& chain_of(const ir::Node& n) { return formula::chain(size_t(view<FormulaP>(n).chain)); }

namespace described {
extern const Description Formula{
    .kind = ir::Kind::Formula, .yaml = "formula",
    .example = "{formula: {iterations: 10, iterate: [box_fold, sphere_fold, {scale: -1.8}, add_c]}}",
    .param_count = count_of<FormulaP>(), .lower = lower, .props = props, .call_args = "", .distance = distance,
    .dual_normals = true, .emit = emit, .emit_orbit = emit_orbit, .emit_dual = emit_dual, .dual_blocker = dual_blocker,
    .orbit_colour = orbit_colour, .de_summary = de_summary,
    .bounds_trust = 0.5,  // the bailout ball is loose: passes/fractal_bounds searches with the estimate
    .bounds_distance = bounds_distance,
    .summary = "a fractal written as a chain of steps, its distance estimate derived from them",
    .docs = k_docs, .explain = explain};
}

}  // namespace sdfc::kinds
