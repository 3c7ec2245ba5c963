#include "domain.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "materials.hpp"
#include "sdfc/expr/expr.hpp"

namespace sdfc::reference::detail {

namespace {

using ir::Kind;

// Coordinates with `axis` moved last (the z-first frame the stdlib uses).
Vec3 to_z(const Vec3& p, int axis) {
  if (axis == 0) return {p[1], p[2], p[0]};
  if (axis == 1) return {p[2], p[0], p[1]};
  return p;
}
Vec3 from_z(const Vec3& q, int axis) {
  if (axis == 0) return {q[2], q[0], q[1]};
  if (axis == 1) return {q[1], q[2], q[0]};
  return q;
}

// Union-style blends (hg_sdf, Quilez), in plain double arithmetic.
double blend_union(int style, double a, double b, double r, double n) {
  switch (style) {
    case 0: {
      double h = std::max(r - std::fabs(a - b), 0.0) / r;
      return std::min(a, b) - h * h * h * r / 6;
    }
    case 1: {
      double m = std::min(a, b);
      return m - r * std::log2(std::exp2((m - a) / r) + std::exp2((m - b) / r));
    }
    case 2: return std::min(std::min(a, b), (a - r + b) * std::sqrt(0.5));
    case 3: return std::max(r, std::min(a, b)) - std::hypot(std::max(r - a, 0.0), std::max(r - b, 0.0));
    case 4: {
      double col = r * std::sqrt(2.0) / ((n - 1) * 2 + std::sqrt(2.0));
      double x = (a + b) * std::sqrt(0.5), y = (b - a) * std::sqrt(0.5);
      x += -std::sqrt(0.5) * r + col * std::sqrt(2.0);
      if (std::fmod(n, 2.0) == 1) y += col;
      double size = 2 * col;
      y = y + size / 2 - size * std::floor((y + size / 2) / size) - size / 2;
      // The columns, cut to the region a < r, b < r (continuously, see blends.cl).
      double cols = std::min(std::hypot(x, y) - col, x);
      return std::min({a, b, std::max(cols, std::max(a, b) - r)});
    }
    case 5: {
      double s = r / n, u = b - r;
      double w = u - a + s, m = 2 * s;
      return std::min(std::min(a, b), 0.5 * (u + a + std::fabs(w - m * std::floor(w / m) - s)));
    }
  }
  return std::min(a, b);
}

}  // namespace

std::optional<Sample> domain_evaluate(const ir::Graph& g, const ir::Node& n, const Vec3& p) {
  const auto& q = n.params;
  auto child = [&](const Vec3& x) { return evaluate(g, n.children[0], x); };
  switch (n.kind) {
    case Kind::Repeat: {
      // Own cell and its neighbour on each repeated axis, plus the bound on every farther copy.
      const ir::Box3& cb = g.node(n.children[0]).props.bounds;
      std::vector<double> opts[3];
      double rest = 1e300;
      for (int i = 0; i < 3; ++i) {
        double s = q[i], cnt = q[3 + i];
        if (cnt == 1) {
          opts[i] = {p[i]};
          continue;
        }
        double half = cnt > 0 ? (cnt - 1) / 2 : 0;
        // std::round rounds halves away from zero, as OpenCL's round does.
        double cell = std::round(p[i] / s + half);
        if (cnt > 0) cell = std::clamp(cell, 0.0, cnt - 1);
        double u = p[i] - s * (cell - half);
        double side = u < 0 ? -1 : 1;
        if (cnt > 0 && (cell + side < 0 || cell + side > cnt - 1)) side = -side;
        opts[i] = {u, p[i] - s * (cell + side - half)};
        rest = std::min(rest, s - std::max(std::fabs(cb.lo[i]), std::fabs(cb.hi[i])) + std::fabs(u));
      }
      Sample best{1e30, 0};
      for (double x : opts[0])
        for (double y : opts[1])
          for (double z : opts[2]) {
            Sample c = child({x, y, z});
            if (c.distance < best.distance) best = c;
          }
      best.distance = std::min(best.distance, rest);
      return best;
    }
    case Kind::Mirror:
      return child({q[0] != 0 ? std::fabs(p[0]) : p[0], q[1] != 0 ? std::fabs(p[1]) : p[1], q[2] != 0 ? std::fabs(p[2]) : p[2]});
    case Kind::PolarRepeat: {
      int axis = int(q[0]);
      Vec3 l = to_z(p, axis);
      double sector = 2 * std::numbers::pi / q[1];
      double a = std::atan2(l[1], l[0]), r = std::hypot(l[0], l[1]);
      double i = std::round(a / sector);
      double j = i + (a - i * sector < 0 ? -1 : 1);
      Sample best{1e30, 0};
      for (double cell : {i, j}) {
        double t = a - cell * sector;
        Sample c = child(from_z({r * std::cos(t), r * std::sin(t), l[2]}, axis));
        if (c.distance < best.distance) best = c;
      }
      return best;
    }
    case Kind::Symmetry: {
      Vec3 v = p;
      if (q[0] != 0) {
        // Octahedral: the chamber x >= y >= z >= 0.
        for (double& c : v) c = std::fabs(c);
        std::sort(v.begin(), v.end(), std::greater<>());
      } else {
        // Tetrahedral: reflect through x = -y, x = -z, y = -z in turn.
        if (v[0] + v[1] < 0) v = {-v[1], -v[0], v[2]};
        if (v[0] + v[2] < 0) v = {-v[2], v[1], -v[0]};
        if (v[1] + v[2] < 0) v = {v[0], -v[2], -v[1]};
      }
      return child(v);
    }
    case Kind::Twist: {
      int axis = int(q[0]);
      Vec3 l = to_z(p, axis);
      double t = -q[1] * l[2];
      return child(from_z({std::cos(t) * l[0] - std::sin(t) * l[1], std::sin(t) * l[0] + std::cos(t) * l[1], l[2]}, axis));
    }
    case Kind::Bend: {
      // Quilez's bend of a bar along the axis: the (axis, next axis) plane turns by rate * t.
      int axis = int(q[0]), next = (axis + 1) % 3;
      double t = q[1] * p[axis], c = std::cos(t), s = std::sin(t);
      Vec3 l = p;
      l[axis] = c * p[axis] - s * p[next];
      l[next] = s * p[axis] + c * p[next];
      return child(l);
    }
    case Kind::Elongate:
      return child({p[0] - std::clamp(p[0], -q[0], q[0]), p[1] - std::clamp(p[1], -q[1], q[1]), p[2] - std::clamp(p[2], -q[2], q[2])});
    case Kind::Round: {
      Sample s = child(p);
      s.distance = s.distance - q[0];
      return s;
    }
    case Kind::Onion: {
      Sample s = child(p);
      s.distance = std::fabs(s.distance) - q[0];
      return s;
    }
    case Kind::Shell: {
      Sample s = child(p);
      s.distance = std::max(s.distance, -s.distance - q[0]);
      return s;
    }
    case Kind::ScaleXYZ: {
      Sample s = child({p[0] / q[0], p[1] / q[1], p[2] / q[2]});
      s.distance = s.distance * std::min({q[0], q[1], q[2]});
      return s;
    }
    case Kind::Displace: {
      Sample s = child(p);
      // time 0 unless the module was taken at another time (at_time.hpp)
      expr::Env env{{"x", p[0]}, {"y", p[1]}, {"z", p[2]}, {"time", 0.0}};
      s.distance += expr::evaluate(g.expressions.at(size_t(q[0])), env);
      return s;
    }
    case Kind::BlendUnion:
    case Kind::BlendIntersection:
    case Kind::BlendDifference: {
      Sample acc = evaluate(g, n.children[0], p);
      int style = int(q[0]);
      for (size_t i = 1; i < n.children.size(); ++i) {
        Sample s = evaluate(g, n.children[i], p);
        // As blend(a, b) of the children's own distances: the union's dual.
        // blend(a, nb): nb is B's distance as it enters, negated for a difference.
        std::function<double(double, double)> blend;
        bool take_b = false;  // B is the nearer child
        double nb = s.distance;
        if (n.kind == Kind::BlendUnion) {
          take_b = s.distance < acc.distance;
          blend = [&](double a, double b) { return blend_union(style, a, b, q[1], q[2]); };
        } else if (n.kind == Kind::BlendIntersection) {
          take_b = s.distance > acc.distance;
          blend = [&](double a, double b) { return -blend_union(style, -a, -b, q[1], q[2]); };
        } else {
          nb = -s.distance;
          blend = [&](double a, double b) { return -blend_union(style, -a, -b, q[1], q[2]); };
        }
        double d = blend(acc.distance, nb);
        if (style < 2) {  // cubic, exponential: the materials mix by B's share
          acc = mix_samples(acc, s, share_of_b(blend, acc.distance, nb), d, take_b ? s.material : acc.material);
        } else if (take_b) {
          acc = s, acc.distance = d;
        } else {
          acc.distance = d;  // the nearer child's material (a difference keeps the first)
        }
      }
      return acc;
    }
    default: break;
  }
  return std::nullopt;
}
}  // namespace sdfc::reference::detail
