// displace: the child's distance plus an expression of x, y, z and time
// (kept in the graph's expression table, by index).
#include "domain_op.hpp"
#include "../codegen/kernel_text.hpp"
#include "sdfc/expr/expr.hpp"
#include "sdfc/kinds/params.hpp"

SDFC_KIND(Displace,           48, "displace",            Transform,  1, "expression",                    "")

namespace sdfc::kinds {
namespace {
using namespace domain;

struct DisplaceP {
  double expression;  // its index in Graph::expressions
};

const expr::ExprPtr& expression_of(const ir::Graph& g, const ir::Node& n) {
  return g.expressions.at(displacement(n));
}

ir::Props props(const ir::Graph& g, const ir::Node& n, const Kid& kid) {
  ir::Props p = kid(0);
  need_bounds(n, p.bounds, "displace");
  const expr::ExprPtr& e = expression_of(g, n);
  auto over = [](const Box3& b) {
    return expr::IntervalEnv{{"x", {b.lo[0], b.hi[0]}}, {"y", {b.lo[1], b.hi[1]}}, {"z", {b.lo[2], b.hi[2]}},
                             {"time", {0, expr::kMaxTime}}};
  };
  // The surface moves by at most max|e| over the region it can move into:
  // grow the box until the bound holds for the grown box itself.
  Box3 inner = p.bounds;
  double m = 0;
  bool settled = false;
  // m rises towards the fixed point from below; the 2% on each round
  // carries it past, where the bound holds (0.1*sin(x)*sin(x) on a
  // sphere crept up for more than 16 rounds without that).
  for (int it = 0; it < 64 && !settled; ++it) {
    double next = expr::evaluate_interval(e, over(inner.padded(m))).magnitude();
    settled = std::isfinite(next) && next <= m;
    m = std::isfinite(next) ? (settled ? m : 1.02 * std::max(m, next)) : next;
    if (!std::isfinite(m)) break;
  }
  if (!settled)
    fail(n.loc, "displace: the displacement grows with the distance from the shape, so it cannot be bounded",
         "use a bounded displacement, e.g. 0.05*sin(10*x)");
  p.bounds = inner.padded(m);
  p.lipschitz_region = steep_region(p.bounds);
  double grad2 = 0;
  for (const char* v : {"x", "y", "z"}) {
    double d = expr::evaluate_interval(expr::derivative(e, v), over(p.lipschitz_region)).magnitude();
    grad2 += d * d;
  }
  double grad = std::sqrt(grad2);
  if (!std::isfinite(grad))
    fail(n.loc, "displace: the displacement's gradient is unbounded over the shape", "avoid division by zero and log near 0");
  // The kernel divides the distance by L: past this, rays would crawl
  // (0.01*sin(exp(100*x)) has L ~ 6e24 and rendered blank).
  constexpr double kMaxDisplaceGradient = 1e4;
  if (grad > kMaxDisplaceGradient)
    fail(n.loc, fmt::format("displace: the displacement's gradient is up to {:.3g} over the shape, more than {:g}; "
                            "the rays would need that many steps per unit of distance",
                            grad, kMaxDisplaceGradient),
         "use a gentler displacement (smaller frequencies)");
  p.lipschitz += grad;
  p.cls = p.lipschitz > 1 ? DistanceClass::Lipschitz : worse(p.cls, DistanceClass::Bound);
  p.cost += 20;
  return p;
}

Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  Sample s = child_at(g, n, p);
  // time 0 unless the module was taken at another time (reference/at_time)
  expr::Env env{{"x", p[0]}, {"y", p[1]}, {"z", p[2]}, {"time", 0.0}};
  s.distance += expr::evaluate(expression_of(g, n), env);
  return s;
}

Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  Carried c = w.child(n.children[0], p);
  const expr::ExprPtr& e = expression_of(w.graph(), n);
  std::string body = expr::to_opencl(
      e, [&](std::string_view var) { return var == "time" ? std::string("time") : p + "." + std::string(var); },
      [&](double x) { return w.lit().typed(x); });
  std::string d = w.var("d");
  w.line(fmt::format("real {} = {} + {};  // displace {}{}", d, c.d, body, codegen::kernel_text(expr::to_string(e)),
                     w.where(n)));
  return with_d(c, d);
}

}  // namespace

size_t displacement(const ir::Node& displace) { return size_t(view<DisplaceP>(displace).expression); }

namespace {
constexpr ParamDoc k_displace_docs[] = {
    {"expr", "expression of x, y, z, time", "", "bounded near the shape", "the displacement"},
};
}  // namespace

namespace described {
extern const Description Displace{.kind = ir::Kind::Displace,
                                  .yaml = "displace",
                                  .example = "{sphere: {radius: 0.7}, displace: {expr: \"0.05*sin(12*x)*sin(12*y)*sin(12*z)\"}}",
                                  .param_count = count_of<DisplaceP>(),
                                  .child_props = props,
                                  .evaluate = evaluate,
                                  .walk = walk,
                                  .summary = "Adds an expression of the point (and time) to the distance. Lipschitz: the expression's gradient is bounded over the node's region and corrected for.",
                                  .written_as = "`displace: {expr}` on any bounded node",
                                  .docs = k_displace_docs};
}

}  // namespace sdfc::kinds
