#include "domain_props.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sdfc/expr/expr.hpp"

namespace sdfc::passes::detail {

namespace {

using ir::Box3;
using ir::DistanceClass;
using ir::Kind;

DistanceClass worse(DistanceClass a, DistanceClass b) { return int(a) > int(b) ? a : b; }

// Largest |coordinate| of the box along axis i.
double reach(const Box3& b, int i) { return std::max(std::fabs(b.lo[i]), std::fabs(b.hi[i])); }

// Distance from `axis` of the box's farthest point.
double radial(const Box3& b, int axis) {
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return std::hypot(reach(b, u), reach(b, v));
}

// The box that holds everything within `radius` of the axis, over the box's
// extent along it.
Box3 around_axis(const Box3& b, int axis, double radius) {
  Box3 r = b;
  for (int i = 0; i < 3; ++i)
    if (i != axis) r.lo[i] = -radius, r.hi[i] = radius;
  return r;
}

void need_bounds(const ir::Node& n, const Box3& b, std::string_view what) {
  if (!b.finite())
    fail(n.loc, fmt::format("{}: the shape it applies to is unbounded, so its distance cannot be bounded", what),
         "apply it to a bounded shape (intersect a plane with a box first)");
}

// Twist (and bend) turn the cross-section by rate * t: at distance rho from
// the axis the map's Jacobian has norm kr/2 + sqrt(1 + (kr/2)^2) with
// kr = |rate| * rho (the largest singular value of [[R, k R J v], [0, 1]]).
double twist_lipschitz(double rate, double rho) {
  double h = std::fabs(rate) * rho / 2;
  return h + std::sqrt(1 + h * h);
}

// Where a steep node's L must hold: its bounds B grown by a margin. Outside
// that region the kernel uses the distance to B, which is at least the
// margin there, so a ray never stops at the region's wall; inside it, the
// segment to the nearest surface point stays in the (convex) region, where
// L holds.
Box3 steep_region(const Box3& b) {
  double size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, b.hi[i] - b.lo[i]);
  return b.padded(0.05 * size + 0.01);
}

}  // namespace

std::optional<ir::Props> domain_props(const ir::Graph& g, const ir::Node& n,
                                      const std::function<ir::Props(size_t)>& kid) {
  const auto& q = n.params;
  ir::Props p;
  switch (n.kind) {
    case Kind::Repeat: {
      p = kid(0);
      need_bounds(n, p.bounds, "repeat");
      const Box3 cell = p.bounds;
      int repeated = 0;
      for (int i = 0; i < 3; ++i) {
        if (q[3 + i] == 1) continue;
        ++repeated;
        const char* axis = i == 0 ? "x" : i == 1 ? "y" : "z";
        // The neighbour cell is evaluated, so the child may reach into it, not past it.
        if (reach(cell, i) >= q[i])
          fail(n.loc, fmt::format("repeat: along {} the shape reaches {:.4g} from its cell centre, not less than the "
                                  "period {:.4g}", axis, reach(cell, i), q[i]),
               "make the period larger than the shape's half width along that axis");
        if (q[3 + i] == 0) {
          p.bounds.lo[i] = -Box3::inf(), p.bounds.hi[i] = Box3::inf();
        } else {
          double half = q[i] * (q[3 + i] - 1) / 2;
          p.bounds.lo[i] -= half, p.bounds.hi[i] += half;
        }
      }
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost = p.cost * (1 << repeated) + 12 * repeated;
      break;
    }
    case Kind::Mirror: {
      p = kid(0);
      for (int i = 0; i < 3; ++i)
        if (q[i] != 0) {
          double hi = std::max(p.bounds.hi[i], 0.0);
          p.bounds.lo[i] = -hi, p.bounds.hi[i] = hi;
        }
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost += 3;
      break;
    }
    case Kind::PolarRepeat: {
      p = kid(0);
      int axis = int(q[0]);
      need_bounds(n, p.bounds, "polar_repeat");
      p.bounds = around_axis(p.bounds, axis, radial(p.bounds, axis));
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost = p.cost * 2 + 40;
      break;
    }
    case Kind::Symmetry: {
      p = kid(0);
      need_bounds(n, p.bounds, "symmetry");
      p.bounds = Box3::cube(std::hypot(reach(p.bounds, 0), reach(p.bounds, 1), reach(p.bounds, 2)));
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost += 12;
      break;
    }
    case Kind::Twist:
    case Kind::Bend: {
      p = kid(0);
      int axis = int(q[0]);
      need_bounds(n, p.bounds, ir::info(n.kind).name);
      // Twist turns about the axis, bend turns the (axis, next) plane about
      // the third axis: both keep the distance from that axis.
      int keep = n.kind == Kind::Twist ? axis : (axis + 2) % 3;
      p.bounds = around_axis(p.bounds, keep, radial(p.bounds, keep));
      p.lipschitz_region = steep_region(p.bounds);
      double rho = radial(p.lipschitz_region, keep);  // the region's farthest point from that axis
      p.lipschitz *= n.kind == Kind::Twist ? twist_lipschitz(q[1], rho) : 1 + std::fabs(q[1]) * rho;
      p.cls = p.lipschitz > 1 ? DistanceClass::Lipschitz : worse(p.cls, DistanceClass::Bound);
      p.cost += 30;
      break;
    }
    case Kind::Elongate:
      p = kid(0);
      for (int i = 0; i < 3; ++i) p.bounds.lo[i] -= q[i], p.bounds.hi[i] += q[i];
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost += 8;
      break;
    case Kind::Round:
    case Kind::Onion:
      p = kid(0);
      if (p.bounds.finite()) p.bounds = p.bounds.padded(q[0]);
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost += 2;
      break;
    case Kind::Shell: p = kid(0); p.cls = worse(p.cls, DistanceClass::Bound); p.cost += 3; break;
    case Kind::ScaleXYZ:
      p = kid(0);
      for (int i = 0; i < 3; ++i) p.bounds.lo[i] *= q[i], p.bounds.hi[i] *= q[i];
      p.cls = worse(p.cls, DistanceClass::Bound);
      p.cost += 6;
      break;
    case Kind::Displace: {
      p = kid(0);
      need_bounds(n, p.bounds, "displace");
      const expr::ExprPtr& e = g.expressions.at(size_t(q[0]));
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
      break;
    }
    case Kind::BlendUnion:
    case Kind::BlendIntersection:
    case Kind::BlendDifference: {
      p.cls = DistanceClass::Bound;
      p.lipschitz = 0;
      p.bounds = kid(0).bounds;
      for (size_t i = 0; i < n.children.size(); ++i) {
        ir::Props c = kid(i);
        p.cls = worse(p.cls, c.cls);
        p.lipschitz = std::max(p.lipschitz, c.lipschitz);
        p.cost += c.cost + 8;
        if (i == 0) continue;
        if (n.kind == Kind::BlendUnion) p.bounds = p.bounds.united(c.bounds);
        if (n.kind == Kind::BlendIntersection) p.bounds = p.bounds.intersected(c.bounds);
      }
      // Material is added only by unions, within the blend radius.
      if (n.kind == Kind::BlendUnion && p.bounds.finite()) p.bounds = p.bounds.padded(q[1]);
      // Chamfer, round and columns combine a and b along the diagonal: where
      // the two gradients agree the blend's gradient reaches sqrt(2).
      int style = int(q[0]);
      if (style == 2 || style == 3 || style == 4) p.lipschitz *= std::sqrt(2.0);
      if (p.lipschitz > 1) p.cls = DistanceClass::Lipschitz;
      break;
    }
    default: return std::nullopt;
  }
  p.known = true;
  p.corrected = false;
  return p;
}

}  // namespace sdfc::passes::detail
