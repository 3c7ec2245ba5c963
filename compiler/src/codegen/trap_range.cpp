#include "trap_range.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "sdfc/reference/evaluator.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;
using ir::NodeId;

// Fractal nodes by the material that colours them (the nearest material
// node above; 0 at the root).
void collect(const ir::Graph& g, NodeId id, int material, std::map<int, std::set<NodeId>>& out) {
  const ir::Node& n = g.node(id);
  if (n.kind == Kind::Material) material = int(n.params[0]);
  if (ir::info(n.kind).category == ir::Category::Fractal) out[material].insert(id);
  for (NodeId c : n.children) collect(g, c, material, out);
}

// The trap or smooth-iteration values at points of a grid over the node's
// bounds (its own frame) that lie within a fifth of a cell of its surface
// (further out the trap grows, and the range would reach past the surface).
void sample_surface(const ir::Graph& g, NodeId id, bool iteration, std::vector<double>& values) {
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
        if (auto c = reference::orbit_colour(n, p)) {
          double v = iteration ? c->iteration : c->trap;
          if (std::isfinite(v)) values.push_back(v);
        }
      }
}

}  // namespace

ir::RenderPlan with_trap_ranges(const ir::Module& m) {
  ir::RenderPlan plan = m.plan;
  bool wanted = false;
  for (const auto& md : plan.materials) wanted = wanted || (!md.trap_palette.empty() && md.trap_range_auto);
  if (!wanted) return plan;
  std::map<int, std::set<NodeId>> fractals;
  collect(*m.graph, m.root, 0, fractals);
  for (size_t i = 0; i < plan.materials.size(); ++i) {
    ir::MaterialDef& md = plan.materials[i];
    if (md.trap_palette.empty() || !md.trap_range_auto) continue;
    std::vector<double> values;
    for (NodeId id : fractals[int(i)])
      sample_surface(*m.graph, id, md.trap_source == ir::MaterialDef::TrapSource::Iteration, values);
    if (values.size() < 16) continue;  // too little surface to measure: the value itself, [0, 1]
    // The 2nd to 98th percentile: a few outlying orbits do not squeeze the rest.
    std::sort(values.begin(), values.end());
    double lo = values[values.size() * 2 / 100], hi = values[values.size() * 98 / 100];
    if (hi - lo < 1e-6) continue;
    md.trap_lo = lo;
    md.trap_hi = hi;
  }
  return plan;
}

}  // namespace sdfc::codegen::detail
