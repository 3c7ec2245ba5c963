// The box that camera.fit frames (see fit_box.hpp).
#include "fit_box.hpp"

#include "sdfc/kinds/registry.hpp"

namespace sdfc::passes::detail {

namespace {

// A node's bounds; where they are unbounded, the union of its children's
// finite boxes through the kinds whose description says so (unions,
// materials, bounding boxes: a union of a fractal and a floor plane gives
// the fractal's box).
std::optional<ir::Box3> finite_part(const ir::Graph& g, ir::NodeId id) {
  const ir::Node& n = g.node(id);
  if (n.props.bounds.finite()) return n.props.bounds;
  const kinds::Description* d = kinds::operation(n.kind);
  if (!d || !d->fit_children) return std::nullopt;
  std::optional<ir::Box3> out;
  for (ir::NodeId c : n.children)
    if (auto b = finite_part(g, c)) out = out ? out->united(*b) : *b;
  return out;
}

}  // namespace

std::optional<ir::Box3> fit_box(const ir::Module& m) { return finite_part(*m.graph, m.root); }

void record_fit_box(ir::Module& m) {
  auto b = fit_box(m);
  m.plan.camera.has_fit_box = b.has_value();
  if (b) m.plan.camera.fit_lo = b->lo, m.plan.camera.fit_hi = b->hi;
}

}  // namespace sdfc::passes::detail
