#pragma once
// Small double-precision helpers the kind descriptions share: boxes for
// bounds and the vector and 2D-profile maths of their reference distances.
#include <algorithm>
#include <cmath>

#include "sdfc/kinds/description.hpp"
#include "sdfc/kinds/lowering.hpp"

namespace sdfc::kinds::math {

inline ir::Box3 box(double x0, double y0, double z0, double x1, double y1, double z1) {
  return {{x0, y0, z0}, {x1, y1, z1}};
}
// A leaf's properties: these bounds and cost, exact unless told.
inline ir::Props leaf(const ir::Box3& b, double cost, ir::DistanceClass cls = ir::DistanceClass::Exact) {
  ir::Props p;
  p.known = true;
  p.bounds = b;
  p.cls = cls;
  p.cost = cost;
  return p;
}

struct V {
  double x, y, z;
};
inline V at(const V3& a) { return {a[0], a[1], a[2]}; }
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double len(V a) { return std::sqrt(dot(a, a)); }
inline V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double sgn(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
inline double len2(double x, double y) { return std::hypot(x, y); }

// A 2D profile distance d extruded along z to |z| <= h (exact).
inline double extrude(double d, double z, double h) {
  double w = std::fabs(z) - h;
  return std::min(std::max(d, w), 0.0) + len2(std::max(d, 0.0), std::max(w, 0.0));
}

// Squared distance from p to the segment a-b.
inline double seg2(V p, V a, V b) {
  V e = b - a, pa = p - a;
  double t = std::clamp(dot(e, pa) / dot(e, e), 0.0, 1.0);
  V d = pa - e * t;
  return dot(d, d);
}

}  // namespace sdfc::kinds::math
