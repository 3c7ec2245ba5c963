#include "trap_range.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "sdfc/reference/evaluator.hpp"
#include "sdfc/kinds/params.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;
using ir::NodeId;

// Fractal nodes by the material that colours them (the nearest material
// node above; 0 at the root).
void collect(const ir::Graph& g, NodeId id, int material, std::map<int, std::set<NodeId>>& out) {
  const ir::Node& n = g.node(id);
  if (n.kind == Kind::Material) material = kinds::material_id(n);
  if (ir::info(n.kind).category == ir::Category::Fractal) out[material].insert(id);
  for (NodeId c : n.children) collect(g, c, material, out);
}

// The trap or smooth-iteration values at points of a grid over the node's
// bounds (its own frame) that lie within a fifth of a cell of its surface
// (further out the trap grows, and the range would reach past the surface).
void sample_surface(const ir::Graph& g, NodeId id, bool iteration, const ir::TrapShape& shape, std::vector<double>& values) {
  const ir::Node& n = g.node(id);
  ir::Box3 b = n.props.bounds;
  if (!b.finite()) b = ir::Box3::cube(2);
  constexpr int kCells = 32;
  double cell = 0;
  for (int a = 0; a < 3; ++a) cell = std::max(cell, (b.hi[a] - b.lo[a]) / kCells);
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j)
      for (int k = 0; k < kCells; ++k) {
        reference::Vec3 p{b.lo[0] + (i + 0.5) * (b.hi[0] - b.lo[0]) / kCells, b.lo[1] + (j + 0.5) * (b.hi[1] - b.lo[1]) / kCells,
                          b.lo[2] + (k + 0.5) * (b.hi[2] - b.lo[2]) / kCells};
        if (std::fabs(reference::evaluate(g, id, p).distance) > 0.2 * cell) continue;
        if (auto c = reference::orbit_colour(n, p, shape)) {
          double v = iteration ? c->iteration : c->trap;
          if (std::isfinite(v)) values.push_back(v);
        }
      }
}

// The 2nd to 98th percentile of the values (a few outlying orbits do not
// squeeze the rest); false when there are too few to measure or they do not spread.
bool percentiles(std::vector<double> values, double& lo, double& hi) {
  if (values.size() < 16) return false;  // too little surface to measure: the value itself, [0, 1]
  std::sort(values.begin(), values.end());
  double a = values[values.size() * 2 / 100], b = values[values.size() * 98 / 100];
  if (b - a < 1e-6) return false;
  lo = a, hi = b;
  return true;
}

// The extent along `axis` of the material's geometry (its material nodes'
// bounds, else the scene's), for a position source.
void position_range(const ir::Module& m, int material, const ir::Vec3d& axis, double& lo, double& hi) {
  ir::Box3 b;
  bool any = false;
  for (NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (n.kind != Kind::Material || kinds::material_id(n) != material || !n.props.bounds.finite()) continue;
    b = any ? b.united(n.props.bounds) : n.props.bounds;
    any = true;
  }
  if (!any) b = m.graph->node(m.root).props.bounds;
  if (!b.finite()) return;  // unbounded: [lo, hi] as given (default [0, 1])
  double a = 0, c = 0;
  for (int k = 0; k < 3; ++k) {
    a += axis[k] * (axis[k] > 0 ? b.lo[k] : b.hi[k]);
    c += axis[k] * (axis[k] > 0 ? b.hi[k] : b.lo[k]);
  }
  if (c - a > 1e-9) lo = a, hi = c;
}

}  // namespace

ir::RenderPlan with_trap_ranges(const ir::Module& m) {
  ir::RenderPlan plan = m.plan;
  bool wanted = false;
  for (const auto& md : plan.materials) {
    wanted = wanted || (!md.trap_palette.empty() && md.trap_range_auto);
    for (const auto& s : md.coloring) wanted = wanted || s.range_auto;
  }
  if (!wanted) return plan;
  std::map<int, std::set<NodeId>> fractals;
  collect(*m.graph, m.root, 0, fractals);
  auto orbit_values = [&](int material, bool iteration, const ir::TrapShape& shape) {
    std::vector<double> values;
    for (NodeId id : fractals[material]) sample_surface(*m.graph, id, iteration, shape, values);
    return values;
  };
  using Source = ir::ColourSource::Kind;
  for (size_t i = 0; i < plan.materials.size(); ++i) {
    ir::MaterialDef& md = plan.materials[i];
    if (!md.trap_palette.empty() && md.trap_range_auto)
      percentiles(orbit_values(int(i), md.trap_source == ir::MaterialDef::TrapSource::Iteration, md.trap_shape), md.trap_lo,
                  md.trap_hi);
    for (auto& s : md.coloring) {
      if (!s.range_auto) continue;
      if (s.kind == Source::Trap || s.kind == Source::Iteration)
        percentiles(orbit_values(int(i), s.kind == Source::Iteration, s.shape), s.lo, s.hi);
      else if (s.kind == Source::Normal) s.lo = -1, s.hi = 1;  // every way the surface can face
      else position_range(m, int(i), s.axis, s.lo, s.hi);
    }
  }
  return plan;
}

}  // namespace sdfc::codegen::detail
