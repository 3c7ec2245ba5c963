// CPU reference evaluator: the IR's distance in double precision, written
// from the formulas, not from the OpenCL stdlib, so the two check each other.
#include "sdfc/reference/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sdfc/kinds/registry.hpp"
#include "domain.hpp"
#include "materials.hpp"
#include "object_set.hpp"

namespace sdfc::reference {

namespace {

using ir::Kind;

double len(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

double smin_poly(double a, double b, double k) {
  double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k / 4;
}
double smax_poly(double a, double b, double k) {
  double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::max(a, b) + h * h * k / 4;
}

// Distance from p to the box (0 inside).
double box_outside(const Vec3& p, const ir::Box3& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i) {
    double c = std::max({b.lo[i] - p[i], p[i] - b.hi[i], 0.0});
    s += c * c;
  }
  return std::sqrt(s);
}

Sample evaluate_node(const ir::Graph& g, ir::NodeId id, const Vec3& p);

}  // namespace

// The node's distance with the correction the emitter applies where L > 1:
// divided by L inside the region where L holds, outside it the distance to
// the node's bounds.
Sample evaluate(const ir::Graph& g, ir::NodeId id, const Vec3& p) {
  Sample s = evaluate_node(g, id, p);
  const ir::Props& pr = g.node(id).props;
  if (!pr.corrected) return s;
  if (pr.lipschitz_region.finite() && box_outside(p, pr.lipschitz_region) > 0)
    s.distance = box_outside(p, pr.bounds);
  else
    s.distance /= pr.lipschitz;
  return s;
}

namespace {

Sample evaluate_node(const ir::Graph& g, ir::NodeId id, const Vec3& p) {
  const ir::Node& n = g.node(id);
  const auto& q = n.params;
  if (const kinds::Description* d = kinds::find(n.kind)) return {d->distance(n, p), 0};
  if (auto d = detail::domain_evaluate(g, n, p)) return *d;
  if (n.kind == Kind::ObjectSet) return detail::object_set_evaluate(n, p);
  switch (n.kind) {
    case Kind::StepFactor: {
      Sample s = evaluate(g, n.children[0], p);
      s.distance *= q[0];
      return s;
    }
    case Kind::Translate: return evaluate(g, n.children[0], {p[0] - q[0], p[1] - q[1], p[2] - q[2]});
    case Kind::Rotate: {
      // Stored local->world; apply the transpose to go world->local.
      Vec3 l{q[0] * p[0] + q[3] * p[1] + q[6] * p[2], q[1] * p[0] + q[4] * p[1] + q[7] * p[2],
             q[2] * p[0] + q[5] * p[1] + q[8] * p[2]};
      return evaluate(g, n.children[0], l);
    }
    case Kind::Scale: {
      Sample s = evaluate(g, n.children[0], {p[0] / q[0], p[1] / q[0], p[2] / q[0]});
      s.distance *= q[0];
      return s;
    }
    case Kind::Bounded: {
      // The box's exact distance is a lower bound of the child's; far enough
      // out it stands in for the child, which is then not evaluated.
      double c[3], h[3];
      for (int i = 0; i < 3; ++i) c[i] = 0.5 * (q[i] + q[i + 3]), h[i] = 0.5 * (q[i + 3] - q[i]);
      double dx = std::fabs(p[0] - c[0]) - h[0], dy = std::fabs(p[1] - c[1]) - h[1], dz = std::fabs(p[2] - c[2]) - h[2];
      double box = len(std::max(dx, 0.0), std::max(dy, 0.0), std::max(dz, 0.0)) + std::min(std::max({dx, dy, dz}), 0.0);
      if (box > q[6]) return {box, 0};
      return evaluate(g, n.children[0], p);
    }
    case Kind::Material: {
      Sample s = evaluate(g, n.children[0], p);
      detail::claim(s, int(q[0]));
      return s;
    }
    case Kind::Union:
    case Kind::SmoothUnion:
    case Kind::Intersection:
    case Kind::SmoothIntersection:
    case Kind::Difference:
    case Kind::SmoothDifference: {
      Sample acc = evaluate(g, n.children[0], p);
      for (size_t i = 1; i < n.children.size(); ++i) {
        Sample s = evaluate(g, n.children[i], p);
        switch (n.kind) {
          case Kind::Union:
            if (s.distance < acc.distance) acc = s;
            break;
          case Kind::SmoothUnion: {
            auto u = [&](double a, double b) { return smin_poly(a, b, q[0]); };
            acc = detail::mix_samples(acc, s, detail::share_of_b(u, acc.distance, s.distance), u(acc.distance, s.distance),
                                      s.distance < acc.distance ? s.material : acc.material);
            break;
          }
          case Kind::Intersection:
            if (s.distance > acc.distance) acc = s;
            break;
          case Kind::SmoothIntersection: {
            auto i = [&](double a, double b) { return smax_poly(a, b, q[0]); };
            acc = detail::mix_samples(acc, s, detail::share_of_b(i, acc.distance, s.distance), i(acc.distance, s.distance),
                                      s.distance > acc.distance ? s.material : acc.material);
            break;
          }
          case Kind::Difference: acc.distance = std::max(acc.distance, -s.distance); break;
          case Kind::SmoothDifference: {
            // The share of B is the derivative in -b, B's own distance negated.
            auto i = [&](double a, double nb) { return smax_poly(a, nb, q[0]); };
            acc = detail::mix_samples(acc, s, detail::share_of_b(i, acc.distance, -s.distance), i(acc.distance, -s.distance),
                                      acc.material);
            break;
          }
          default: break;
        }
      }
      return acc;
    }
    // Described kinds (sdfc/kinds/): their description above.
    default: break;
    // Domain operations and blends: domain_evaluate above.
    case Kind::Repeat: case Kind::Mirror: case Kind::PolarRepeat: case Kind::Symmetry: case Kind::Twist:
    case Kind::Bend: case Kind::Elongate: case Kind::Round: case Kind::Onion: case Kind::Shell:
    case Kind::Displace: case Kind::ScaleXYZ: case Kind::BlendUnion: case Kind::BlendIntersection:
    case Kind::BlendDifference: break;
  }
  return {0, 0};
}

}  // namespace

}  // namespace sdfc::reference

namespace sdfc::reference {

Look evaluate_material(const ir::Module& m, const Vec3& p) {
  Sample s = evaluate(*m.graph, m.root, p);
  std::vector<std::pair<int, double>> shares = s.shares;
  if (shares.empty()) shares = {{s.material, 1.0}};
  Look look{{0, 0, 0}, 0, 0, 0, s.material};
  for (const auto& [id, w] : shares) {
    const ir::MaterialDef& md = m.plan.materials.at(size_t(id));
    Vec3 albedo = md.color;
    if (!md.trap_palette.empty())  // trap 0: the palette's first colour
      for (int c = 0; c < 3; ++c) albedo[c] += (md.trap_palette[0][c] - albedo[c]) * md.trap_mix;
    for (int c = 0; c < 3; ++c) look.albedo[c] += w * albedo[c];
    look.specular += w * md.specular;
    look.shininess += w * md.shininess;
    look.reflectivity += w * md.reflectivity;
  }
  return look;
}

}  // namespace sdfc::reference
