// infer_properties: bottom-up bounds, distance class, Lipschitz constant and
// cost for every node. Bounds are where the surface can be (outside them the
// distance is positive); the emitter uses the root's for the ray interval.
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "fractal_bounds.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace {

using ir::Box3;
using ir::DistanceClass;
using ir::Kind;

// The less trustworthy of two classes (exact < bound < estimate < lipschitz).
DistanceClass worse(DistanceClass a, DistanceClass b) { return int(a) > int(b) ? a : b; }

ir::Props infer(const ir::Graph& g, const ir::Node& n) {
  // A child the emitter corrects reaches its parent as a bound with L = 1.
  std::function<ir::Props(size_t)> kid = [&](size_t i) {
    ir::Props c = g.node(n.children[i]).props;
    if (c.corrected) c.lipschitz = 1, c.cls = DistanceClass::Bound;
    c.corrected = false;
    c.lipschitz_region = Box3::everything();
    return c;
  };
  if (const kinds::Description* d = kinds::find(n.kind)) return d->props(n);
  if (const kinds::Description* d = kinds::operation(n.kind)) {
    ir::Props o = d->child_props(g, n, kid);
    o.known = true;
    o.corrected = false;
    return o;
  }
  throw std::logic_error(std::string("infer_properties: kind '") + std::string(ir::info(n.kind).name) + "' has no description");
}

// A node with animated parameters: the properties at every corner of the
// parameters' ranges over time (interval arithmetic over [0, kMaxTime]),
// united. This is conservative for the properties the parameters move
// monotonically (sizes, offsets, powers, scales) and for rotations, whose
// entries are bounded by [-1, 1] one by one.
ir::Props infer_animated(const ir::Graph& g, const ir::Node& n) {
  std::vector<size_t> which;
  std::vector<expr::Interval> span;
  for (size_t i = 0; i < n.anim.size(); ++i) {
    if (!n.anim[i]) continue;
    expr::Interval r = expr::evaluate_interval(n.anim[i], {{"time", {0, expr::kMaxTime}}});
    if (n.kind == Kind::Rotate) r = {std::max(r.lo, -1.0), std::min(r.hi, 1.0)};
    which.push_back(i);
    span.push_back(r);
  }
  ir::Node at = n;
  at.anim.clear();
  ir::Props out;
  for (unsigned corner = 0; corner < (1u << which.size()); ++corner) {
    for (size_t k = 0; k < which.size(); ++k) at.params[which[k]] = corner & (1u << k) ? span[k].hi : span[k].lo;
    ir::Props p = infer(g, at);
    if (corner == 0) {
      out = p;
      continue;
    }
    out.bounds = out.bounds.united(p.bounds);
    out.lipschitz_region = out.lipschitz_region.united(p.lipschitz_region);
    out.cls = worse(out.cls, p.cls);
    out.lipschitz = std::max(out.lipschitz, p.lipschitz);
    out.cost = std::max(out.cost, p.cost);
  }
  if (n.kind == Kind::Rotate && !n.children.empty()) {
    // A rotation keeps the child within the ball around the origin that holds its bounds.
    const Box3& b = g.node(n.children[0]).props.bounds;
    if (b.finite()) {
      double r2 = 0;
      for (int i = 0; i < 3; ++i) r2 += std::max(b.lo[i] * b.lo[i], b.hi[i] * b.hi[i]);
      out.bounds = out.bounds.intersected(Box3::cube(std::sqrt(r2)));
    }
  }
  out.cost += 10 * double(which.size());  // the parameters are computed per evaluation
  return out;
}

}  // namespace

ir::Module infer_properties(ir::Module m) {
  ir::Graph& g = *m.graph;
  for (ir::NodeId id : g.postorder(m.root)) {
    const ir::Node& n = g.node(id);
    ir::Props p = n.animated() ? infer_animated(g, n) : infer(g, n);
    p.bounds = detail::fractal_bounds(g, id, p.bounds);
    p.corrected = m.plan.march.lipschitz_correction && p.lipschitz > 1 + 1e-9;
    g.mutable_node(id).props = p;
  }
  return m;
}

}  // namespace sdfc::passes
