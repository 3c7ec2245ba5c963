#include "catalogue.hpp"

#include <algorithm>
#include <cmath>

namespace sdfc::reference::detail {

namespace {

struct V {
  double x, y, z;
};
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double len(V a) { return std::sqrt(dot(a, a)); }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double sgn(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
double len2(double x, double y) { return std::hypot(x, y); }

// A 2D profile distance d extruded along z to |z| <= h (exact).
double extrude(double d, double z, double h) {
  double w = std::fabs(z) - h;
  return std::min(std::max(d, w), 0.0) + len2(std::max(d, 0.0), std::max(w, 0.0));
}

// Squared distance from p to the segment a-b.
double seg2(V p, V a, V b) {
  V e = b - a, pa = p - a;
  double t = std::clamp(dot(e, pa) / dot(e, e), 0.0, 1.0);
  V d = pa - e * t;
  return dot(d, d);
}

// Unsigned distance to a planar convex polygon: to its plane when the
// projection falls inside every edge, else to the nearest edge.
double polygon(V p, const V* c, int n) {
  V nor = cross(c[1] - c[0], c[n - 1] - c[0]);
  bool inside = true;
  double edges = 1e300;
  for (int i = 0; i < n; ++i) {
    V a = c[i], b = c[(i + 1) % n];
    if (dot(cross(b - a, nor), p - a) > 0) inside = false;
    edges = std::min(edges, seg2(p, a, b));
  }
  if (inside) return std::fabs(dot(nor, p - c[0])) / len(nor);
  return std::sqrt(edges);
}

double cone(V p, double r, double hh) {
  // Profile: apex A = (0, hh), base rim B = (r, -hh), base centre (0, -hh).
  double x = len2(p.x, p.y), y = p.z;
  double ex = r, ey = -2 * hh;  // apex -> rim
  double t = std::clamp((x * ex + (y - hh) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
  double side = len2(x - ex * t, y - hh - ey * t);
  double base = len2(x - std::min(x, r), y + hh);
  double d = std::min(side, base);
  bool inside = y > -hh && y < hh && x < r * (hh - y) / (2 * hh);
  return inside ? -d : d;
}

double capped_cone(V p, double h, double r1, double r2) {
  double x = len2(p.x, p.y), y = p.z;
  // Nearest point on the slanted side (bottom rim to top rim) and on the caps.
  double ex = r2 - r1, ey = 2 * h;
  double t = std::clamp(((x - r1) * ex + (y + h) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
  double side = len2(x - r1 - ex * t, y + h - ey * t);
  double top = len2(x - std::min(x, r2), y - h), bottom = len2(x - std::min(x, r1), y + h);
  double d = std::min({side, top, bottom});
  bool inside = std::fabs(y) < h && x < r1 + (r2 - r1) * (y + h) / (2 * h);
  return inside ? -d : d;
}

double round_cone(V p, double r1, double r2, double hh) {
  double x = len2(p.x, p.y), y = p.z + hh, L = 2 * hh;
  double b = (r1 - r2) / L, a = std::sqrt(1 - b * b);
  double k = -b * x + a * y;
  if (k < 0) return len2(x, y) - r1;
  if (k > a * L) return len2(x, y - L) - r2;
  return x * a + y * b - r1;
}

double octahedron(V p, double s) {
  p = {std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)};
  double m = p.x + p.y + p.z - s;
  V q;
  if (3 * p.x < m) q = p;
  else if (3 * p.y < m) q = {p.y, p.z, p.x};
  else if (3 * p.z < m) q = {p.z, p.x, p.y};
  else return m / std::sqrt(3.0);
  double k = std::clamp(0.5 * (q.z - q.y + s), 0.0, s);
  return len({q.x, q.y - s + k, q.z - k});
}

// Signed 2D distance to a convex polygon with counter-clockwise corners c.
double convex2(double x, double y, const V* c, int n) {
  double e2 = 1e300;
  for (int i = 0; i < n; ++i) e2 = std::min(e2, seg2({x, y, 0}, c[i], c[(i + 1) % n]));
  double d = std::sqrt(e2);
  for (int i = 0; i < n; ++i) {
    V e = c[(i + 1) % n] - c[i];
    if (e.x * (y - c[i].y) - e.y * (x - c[i].x) < 0) return d;  // right of an edge: outside
  }
  return -d;
}

// Regular hexagon with flat sides at y = +-a: corners every 60 degrees.
double hexagon(double x, double y, double a) {
  V c[6];
  double r = 2 * a / std::sqrt(3.0);
  for (int i = 0; i < 6; ++i) c[i] = {r * std::cos(i * M_PI / 3), r * std::sin(i * M_PI / 3), 0};
  return convex2(x, y, c, 6);
}

// Equilateral triangle (+-r, -r/sqrt3), (0, 2r/sqrt3).
double triangle2(double x, double y, double r) {
  const double s3 = std::sqrt(3.0);
  V c[3] = {{-r, -r / s3, 0}, {r, -r / s3, 0}, {0, 2 * r / s3, 0}};
  return convex2(x, y, c, 3);
}

// Squared distance in the base plane from (x, y)/base to the unit square.
double base_gap2(V p, double base) {
  double gx = std::max(std::fabs(p.x) / base - 0.5, 0.0), gy = std::max(std::fabs(p.y) / base - 0.5, 0.0);
  return gx * gx + gy * gy;
}

double pyramid(V p, double base, double height) {
  // Unit base pyramid (Quilez), scaled by the base.
  double h = height / base;
  double x = std::fabs(p.x) / base, z = std::fabs(p.y) / base, y = (p.z + height / 2) / base;
  if (z > x) std::swap(x, z);
  x -= 0.5, z -= 0.5;
  double m2 = h * h + 0.25;
  double qx = z, qy = h * y - 0.5 * x, qz = h * x + 0.5 * y;
  double s = std::max(-qx, 0.0);
  double t = std::clamp((qy - 0.5 * z) / (m2 + 0.25), 0.0, 1.0);
  double a = m2 * (qx + s) * (qx + s) + qy * qy;
  double b = m2 * (qx + 0.5 * t) * (qx + 0.5 * t) + (qy - m2 * t) * (qy - m2 * t);
  double d2 = std::min(qy, -qx * m2 - qy * 0.5) > 0 ? 0 : std::min(a, b);
  double side = std::sqrt((d2 + qz * qz) / m2) * sgn(std::max(qz, -y));
  // Quilez's formula measures to the sloping faces; the base face is ours.
  if (y < 0) return std::sqrt(base_gap2(p, base) + y * y) * base;
  return std::max(side, -y) * base;
}

double box_frame(V p, V b, double e) {
  p = {std::fabs(p.x) - b.x, std::fabs(p.y) - b.y, std::fabs(p.z) - b.z};
  V q = {std::fabs(p.x + e) - e, std::fabs(p.y + e) - e, std::fabs(p.z + e) - e};
  auto bar = [](double x, double y, double z) {
    return len({std::max(x, 0.0), std::max(y, 0.0), std::max(z, 0.0)}) + std::min(std::max({x, y, z}), 0.0);
  };
  return std::min({bar(p.x, q.y, q.z), bar(q.x, p.y, q.z), bar(q.x, q.y, p.z)});
}

}  // namespace

std::optional<double> catalogue_distance(const ir::Node& n, const Vec3& pa) {
  using ir::Kind;
  const auto& q = n.params;
  V p{pa[0], pa[1], pa[2]};
  auto at = [&](size_t i) { return V{q[i], q[i + 1], q[i + 2]}; };
  switch (n.kind) {
    case Kind::Cone: return cone(p, q[0], q[1]);
    case Kind::CappedCone: return capped_cone(p, q[0], q[1], q[2]);
    case Kind::RoundCone: return round_cone(p, q[0], q[1], q[2]);
    case Kind::Ellipsoid: {
      double k0 = len({p.x / q[0], p.y / q[1], p.z / q[2]});
      double k1 = len({p.x / (q[0] * q[0]), p.y / (q[1] * q[1]), p.z / (q[2] * q[2])});
      double rmin = std::min({q[0], q[1], q[2]});
      return std::max(k1 > 0 ? k0 * (k0 - 1) / k1 : 0.0, (k0 - 1) * rmin);
    }
    case Kind::Octahedron: return octahedron(p, q[0]);
    case Kind::HexPrism: return extrude(hexagon(p.x, p.y, q[0]), p.z, q[1]);
    case Kind::TriPrism: return extrude(triangle2(p.x, p.y, q[0]), p.z, q[1]);
    case Kind::Link: {
      double y = std::max(std::fabs(p.y) - q[0], 0.0);
      return len2(len2(p.x, y) - q[1], p.z) - q[2];
    }
    case Kind::RoundedCylinder: return extrude(len2(p.x, p.y) - q[0] + q[2], p.z, q[1] - q[2]) - q[2];
    case Kind::Pyramid: return pyramid(p, q[0], q[1]);
    case Kind::Triangle: {
      V c[3] = {at(0), at(3), at(6)};
      return polygon(p, c, 3) - q[9];
    }
    case Kind::Quad: {
      V c[4] = {at(0), at(3), at(6), at(9)};
      return polygon(p, c, 4) - q[12];
    }
    case Kind::BoxFrame: return box_frame(p, at(0), q[3]);
    default: return std::nullopt;
  }
}

}  // namespace sdfc::reference::detail
