#include "catalogue_props.hpp"

#include <algorithm>
#include <cmath>

namespace sdfc::passes::detail {

namespace {
ir::Box3 box(double x0, double y0, double z0, double x1, double y1, double z1) { return {{x0, y0, z0}, {x1, y1, z1}}; }

// The box around a set of corners, grown by the slab's half thickness.
ir::Box3 hull(const std::vector<double>& q, int corners, double pad) {
  ir::Box3 b{{ir::Box3::inf(), ir::Box3::inf(), ir::Box3::inf()}, {-ir::Box3::inf(), -ir::Box3::inf(), -ir::Box3::inf()}};
  for (int c = 0; c < corners; ++c)
    for (int i = 0; i < 3; ++i) b.lo[i] = std::min(b.lo[i], q[c * 3 + i]), b.hi[i] = std::max(b.hi[i], q[c * 3 + i]);
  return b.padded(pad);
}
}  // namespace

std::optional<ir::Props> catalogue_props(const ir::Node& n) {
  using ir::Kind;
  const auto& q = n.params;
  ir::Props p;
  p.known = true;
  switch (n.kind) {
    case Kind::Cone: p.bounds = box(-q[0], -q[0], -q[1], q[0], q[0], q[1]); p.cost = 30; break;
    case Kind::CappedCone: {
      double r = std::max(q[1], q[2]);
      p.bounds = box(-r, -r, -q[0], r, r, q[0]);
      p.cost = 32;
      break;
    }
    case Kind::RoundCone: {
      double r = std::max(q[0], q[1]);
      p.bounds = box(-r, -r, -q[2] - q[0], r, r, q[2] + q[1]);
      p.cost = 26;
      break;
    }
    case Kind::Ellipsoid:
      p.bounds = box(-q[0], -q[1], -q[2], q[0], q[1], q[2]);
      p.cls = ir::DistanceClass::Bound;
      p.cost = 20;
      break;
    case Kind::Octahedron: p.bounds = ir::Box3::cube(q[0]); p.cost = 28; break;
    case Kind::HexPrism: {
      double c = q[0] * 2 / std::sqrt(3.0);  // circumradius
      p.bounds = box(-c, -c, -q[1], c, c, q[1]);
      p.cost = 26;
      break;
    }
    case Kind::TriPrism: {
      double c = q[0] * 2 / std::sqrt(3.0);
      p.bounds = box(-q[0], -c, -q[1], q[0], c, q[1]);
      p.cost = 24;
      break;
    }
    case Kind::Link: {
      double r = q[1] + q[2];
      p.bounds = box(-r, -q[0] - r, -q[2], r, q[0] + r, q[2]);
      p.cost = 14;
      break;
    }
    case Kind::RoundedCylinder: p.bounds = box(-q[0], -q[0], -q[1], q[0], q[0], q[1]); p.cost = 16; break;
    case Kind::Pyramid: p.bounds = box(-q[0] / 2, -q[0] / 2, -q[1] / 2, q[0] / 2, q[0] / 2, q[1] / 2); p.cost = 40; break;
    case Kind::Triangle: p.bounds = hull(q, 3, q[9]); p.cost = 70; break;
    case Kind::Quad: p.bounds = hull(q, 4, q[12]); p.cost = 95; break;
    case Kind::BoxFrame: p.bounds = box(-q[0], -q[1], -q[2], q[0], q[1], q[2]); p.cost = 45; break;
    default: return std::nullopt;
  }
  return p;
}

}  // namespace sdfc::passes::detail
