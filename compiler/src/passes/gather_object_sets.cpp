// gather_object_sets: a union whose children that are spheres or boxes
// (translated, with or without a material) or small smooth unions of them
// are worth_a_set (sdfc/ir/object_set.hpp: enough of them, holding enough
// primitives) becomes one object_set node whose numbers are
// data (sdfc/ir/object_set.hpp): the kernel walks a bounding-volume
// hierarchy over them instead of evaluating every child at every step, and
// its source no longer grows with the scene. Smaller unions stay code, so
// small scenes keep their fully specialised kernels. Other children of the
// union (a floor, a fractal) stay beside the set.
//
// It runs last: the facts `analyse` recorded and the bounding boxes already
// inserted hold for the set as for the union it replaces.
#include <algorithm>
#include <cmath>
#include <optional>

#include "rewrite.hpp"
#include "sdfc/ir/object_set.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace {

using ir::Kind;
namespace os = ir::object_set;

// Below a box test in front of a child: the set's own boxes replace it.
const ir::Node& unboxed(const ir::Graph& g, const ir::Node& n) {
  return n.kind == Kind::Bounded ? g.node(n.children[0]) : n;
}

// A translated sphere or axis-aligned box, with the material nearest it
// (`material` is the one above it; an inner one wins).
std::optional<os::Prim> primitive(const ir::Graph& g, const ir::Node& top, int& material) {
  const ir::Node* n = &top;
  if (n->animated()) return std::nullopt;
  if (n->kind == Kind::Material) material = kinds::material_id(*n), n = &g.node(n->children[0]);
  os::Prim p;
  if (n->animated()) return std::nullopt;
  if (n->kind == Kind::Translate) {
    p.center = kinds::translation(*n);
    n = &g.node(n->children[0]);
  }
  if (n->animated() || n->props.corrected) return std::nullopt;
  if (n->kind == Kind::Sphere) p.type = os::kSphere, p.size = {kinds::sphere_radius(*n), 0, 0};
  else if (n->kind == Kind::Box)
    p.type = os::kBox, p.size = kinds::box_half_extent(*n), p.edge = kinds::box_edge_radius(*n);
  else
    return std::nullopt;
  return p;
}

// A child of the union as an item: one primitive, or a smooth union of
// primitives that all show one material (a blend that mixes materials stays code).
std::optional<os::Item> item(const ir::Graph& g, const ir::Node& child) {
  const ir::Node* n = &unboxed(g, child);
  os::Item it;
  if (n->animated()) return std::nullopt;
  if (n->kind == Kind::Material && g.node(n->children[0]).kind == Kind::SmoothUnion) {
    it.material = kinds::material_id(*n);
    n = &unboxed(g, g.node(n->children[0]));
  }
  if (n->kind != Kind::SmoothUnion) {
    auto p = primitive(g, *n, it.material);
    if (!p) return std::nullopt;
    it.prims = {*p};
    return it;
  }
  if (n->animated() || n->props.corrected || !(kinds::smooth_radius(*n) > 0)) return std::nullopt;
  it.blend = kinds::smooth_radius(*n);
  std::optional<int> shown;
  for (ir::NodeId c : n->children) {
    int m = it.material;
    auto p = primitive(g, unboxed(g, g.node(c)), m);
    if (!p || (shown && *shown != m)) return std::nullopt;
    shown = m;
    it.prims.push_back(*p);
  }
  it.material = *shown;
  return it;
}

}  // namespace

ir::Module gather_object_sets(ir::Module m) {
  if (m.plan.march.precision != ir::Precision::Float || m.plan.march.normals == ir::NormalMethod::Dual) return m;
  size_t offset = 0;  // each set's floats follow the previous set's in the scene data buffer
  const ir::Graph& old = *m.graph;
  return detail::rewrite(std::move(m), [&](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    // An unchanged node; above a set its cost changes by what its children's did.
    auto keep = [&](std::vector<ir::NodeId> children) {
      ir::Props p = n.props;
      for (size_t i = 0; i < children.size(); ++i)
        p.cost += b.graph().node(children[i]).props.cost - old.node(n.children[i]).props.cost;
      ir::NodeId id = b.copy(n, std::move(children));
      b.graph().mutable_node(id).props = p;
      return id;
    };
    if (n.kind != Kind::Union || n.children.size() < os::kSetMinChildren) return keep(std::move(kids));
    std::vector<os::Item> items;
    std::vector<ir::NodeId> rest;
    for (size_t i = 0; i < n.children.size(); ++i) {
      auto it = item(old, old.node(n.children[i]));
      if (it) items.push_back(std::move(*it));
      else rest.push_back(kids[i]);
    }
    size_t prims = 0;
    for (const os::Item& it : items) prims += it.prims.size();
    if (!os::worth_a_set(items.size(), prims)) return keep(std::move(kids));
    const double cost = os::worst_cost(items);  // a walk, not every child
    std::vector<double> q = os::pack(std::move(items), offset);
    offset += q.size() - os::kHeader;
    ir::NodeId set = b.make(Kind::ObjectSet, std::move(q), {}, n.loc);
    ir::Props p = n.props;
    p.cost = std::max(cost, 100.0);
    b.graph().mutable_node(set).props = p;
    if (rest.empty()) return set;
    rest.push_back(set);
    ir::NodeId id = b.copy(n, rest);
    p.cost = 0;
    for (ir::NodeId k : rest) p.cost += b.graph().node(k).props.cost + 1;
    b.graph().mutable_node(id).props = p;
    return id;
  });
}

}  // namespace sdfc::passes
