// CPU reference evaluator: the IR's distance in double precision, written
// from the formulas, not from the OpenCL stdlib, so the two check each other.
#include "sdfc/reference/evaluator.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "sdfc/kinds/registry.hpp"
#include "materials.hpp"

namespace sdfc::reference {

namespace {

using ir::Kind;

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
  if (const kinds::Description* d = kinds::find(n.kind)) return {d->distance(n, p), 0};
  if (const kinds::Description* d = kinds::operation(n.kind)) return d->evaluate(g, n, p);
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
