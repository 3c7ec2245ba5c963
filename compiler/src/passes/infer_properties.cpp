// infer_properties: bottom-up bounds, distance class, Lipschitz constant and
// cost for every node. Bounds are where the surface can be (outside them the
// distance is positive); the emitter uses the root's for the ray interval.
#include <algorithm>
#include <cmath>
#include <functional>

#include "domain_props.hpp"
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

Box3 rotated(const Box3& b, const std::vector<double>& m) {
  if (!b.finite()) return Box3::everything();
  Box3 r{{Box3::inf(), Box3::inf(), Box3::inf()}, {-Box3::inf(), -Box3::inf(), -Box3::inf()}};
  for (int corner = 0; corner < 8; ++corner) {
    double p[3] = {corner & 1 ? b.hi[0] : b.lo[0], corner & 2 ? b.hi[1] : b.lo[1], corner & 4 ? b.hi[2] : b.lo[2]};
    for (int i = 0; i < 3; ++i) {
      double v = m[i * 3] * p[0] + m[i * 3 + 1] * p[1] + m[i * 3 + 2] * p[2];
      r.lo[i] = std::min(r.lo[i], v);
      r.hi[i] = std::max(r.hi[i], v);
    }
  }
  return r;
}

ir::Props infer(const ir::Graph& g, const ir::Node& n) {
  ir::Props p;
  p.known = true;
  const auto& q = n.params;
  // A child the emitter corrects reaches its parent as a bound with L = 1.
  std::function<ir::Props(size_t)> kid = [&](size_t i) {
    ir::Props c = g.node(n.children[i]).props;
    if (c.corrected) c.lipschitz = 1, c.cls = DistanceClass::Bound;
    c.corrected = false;
    c.lipschitz_region = Box3::everything();
    return c;
  };
  if (const kinds::Description* d = kinds::find(n.kind)) return d->props(n);
  if (auto d = detail::domain_props(g, n, kid)) return *d;
  switch (n.kind) {
    case Kind::StepFactor:
      // A factor <= 1 keeps a bound a bound; above 1 nothing is promised.
      p = kid(0);
      if (q[0] > 1) p.cls = worse(p.cls, DistanceClass::Estimate);
      p.cost += 1;
      break;
    case Kind::Translate: {
      p = kid(0);
      for (int i = 0; i < 3; ++i) p.bounds.lo[i] += q[i], p.bounds.hi[i] += q[i];
      p.cost += 3;
      break;
    }
    case Kind::Rotate:
      p = kid(0);
      p.bounds = rotated(p.bounds, q);
      p.cost += 15;
      break;
    case Kind::Scale:
      p = kid(0);
      for (int i = 0; i < 3; ++i) p.bounds.lo[i] *= q[0], p.bounds.hi[i] *= q[0];
      p.cost += 4;
      break;
    case Kind::Material: p = kid(0); p.cost += 1; break;
    case Kind::Bounded: p = kid(0); p.cost += 16; break;  // the box test in front
    case Kind::Union:
    case Kind::Intersection:
    case Kind::Difference:
    case Kind::SmoothUnion:
    case Kind::SmoothIntersection:
    case Kind::SmoothDifference: {
      // min/max of distances is a bound (exact outside for a union, not inside).
      p.cls = DistanceClass::Bound;
      p.lipschitz = 0;
      p.bounds = kid(0).bounds;
      for (size_t i = 0; i < n.children.size(); ++i) {
        const ir::Props& c = kid(i);
        p.cls = worse(p.cls, c.cls);
        p.lipschitz = std::max(p.lipschitz, c.lipschitz);
        p.cost += c.cost + 2;
        if (i == 0) continue;
        if (n.kind == Kind::Union || n.kind == Kind::SmoothUnion) p.bounds = p.bounds.united(c.bounds);
        if (n.kind == Kind::Intersection || n.kind == Kind::SmoothIntersection) p.bounds = p.bounds.intersected(c.bounds);
      }
      // Each fold of a smooth union subtracts at most radius/4, so n children
      // reach at most (n - 1) * radius/4 beyond the union of their bounds.
      if (n.kind == Kind::SmoothUnion && p.bounds.finite())
        p.bounds = p.bounds.padded(double(n.children.size() - 1) * q[0] * 0.25);
      break;
    }
    // Described kinds (sdfc/kinds/): their description above.
    default: break;
    // Domain operations and blends: domain_props above.
    case Kind::Repeat: case Kind::Mirror: case Kind::PolarRepeat: case Kind::Symmetry: case Kind::Twist:
    case Kind::Bend: case Kind::Elongate: case Kind::Round: case Kind::Onion: case Kind::Shell:
    case Kind::Displace: case Kind::ScaleXYZ: case Kind::BlendUnion: case Kind::BlendIntersection:
    case Kind::BlendDifference: break;
  }
  return p;
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
