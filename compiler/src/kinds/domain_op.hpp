#pragma once
// What the domain operations share (repeat.cpp, mirror.cpp, twist_bend.cpp,
// ...): box arithmetic for their bounds, the z-first frame of their axis and
// the reference evaluation of their only child.
#include <algorithm>
#include <cmath>
#include <functional>
#include <string_view>

#include <fmt/format.h>

#include "sdfc/kinds/description.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "walker.hpp"

namespace sdfc::kinds::domain {

using ir::Box3;
using ir::DistanceClass;
using reference::Sample;
using Kid = std::function<ir::Props(size_t)>;

// The less trustworthy of two classes (exact < bound < estimate < lipschitz).
inline DistanceClass worse(DistanceClass a, DistanceClass b) { return int(a) > int(b) ? a : b; }

// Largest |coordinate| of the box along axis i.
inline double reach(const Box3& b, int i) { return std::max(std::fabs(b.lo[i]), std::fabs(b.hi[i])); }

// Distance from `axis` of the box's farthest point.
inline double radial(const Box3& b, int axis) {
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  return std::hypot(reach(b, u), reach(b, v));
}

// The box that holds everything within `radius` of the axis, over the box's
// extent along it.
inline Box3 around_axis(const Box3& b, int axis, double radius) {
  Box3 r = b;
  for (int i = 0; i < 3; ++i)
    if (i != axis) r.lo[i] = -radius, r.hi[i] = radius;
  return r;
}

inline void need_bounds(const ir::Node& n, const Box3& b, std::string_view what) {
  if (!b.finite())
    fail(n.loc, fmt::format("{}: the shape it applies to is unbounded, so its distance cannot be bounded", what),
         "apply it to a bounded shape (intersect a plane with a box first)");
}

// Where a steep node's L must hold: its bounds B grown by a margin. Outside
// that region the kernel uses the distance to B, which is at least the
// margin there, so a ray never stops at the region's wall; inside it, the
// segment to the nearest surface point stays in the (convex) region, where
// L holds.
inline Box3 steep_region(const Box3& b) {
  double size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, b.hi[i] - b.lo[i]);
  return b.padded(0.05 * size + 0.01);
}

// The child's props, its class at best a bound, plus `cost`: a map that
// keeps the child's bounds.
inline ir::Props bound_of(const Kid& kid, double cost) {
  ir::Props p = kid(0);
  p.cls = worse(p.cls, DistanceClass::Bound);
  p.cost += cost;
  return p;
}

// Coordinates with `axis` moved last (the z-first frame the stdlib uses).
inline V3 to_z(const V3& p, int axis) {
  if (axis == 0) return {p[1], p[2], p[0]};
  if (axis == 1) return {p[2], p[0], p[1]};
  return p;
}
inline V3 from_z(const V3& q, int axis) {
  if (axis == 0) return {q[2], q[0], q[1]};
  if (axis == 1) return {q[1], q[2], q[0]};
  return q;
}

// The only child's sample at p.
inline Sample child_at(const ir::Graph& g, const ir::Node& n, const V3& p) {
  return reference::evaluate(g, n.children[0], p);
}
// The nearest of the only child's samples over several points.
template <class Points>
Sample nearest_at(const ir::Graph& g, const ir::Node& n, const Points& points) {
  Sample best{1e30, 0};
  for (const V3& x : points) {
    Sample c = child_at(g, n, x);
    if (c.distance < best.distance) best = c;
  }
  return best;
}

}  // namespace sdfc::kinds::domain
