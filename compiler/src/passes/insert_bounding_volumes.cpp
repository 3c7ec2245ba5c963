// insert_bounding_volumes: put a cheap box test in front of expensive
// subtrees (fractals, large unions) whose bounds are finite. The box
// distance is a lower bound of the subtree's distance, so while a point is
// farther than a margin from the box the subtree need not be evaluated: a
// ray crossing the floor under a fractal never runs the fractal's orbit.
//
// Only children of unions (plain or smooth) and the root are wrapped: min
// and smooth-min are monotone, so a smaller (still lower-bound) argument
// keeps the result a lower bound. The subtracted side of a difference would
// not be (-box > -d), so it is left alone.
#include <algorithm>

#include "rewrite.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace {

// Below this estimated cost (flops per evaluation) the box test costs about
// as much as it saves.
constexpr double kMinCost = 100;

bool worth_bounding(const ir::Node& n) {
  return n.props.known && n.props.cost >= kMinCost && n.props.bounds.finite() && n.kind != ir::Kind::Bounded;
}

ir::NodeId wrap(ir::Builder& b, ir::NodeId child) {
  const ir::Node c = b.graph().node(child);  // copy: make() may grow the graph
  const ir::Box3& bx = c.props.bounds;
  double extent = 0;
  for (int i = 0; i < 3; ++i) extent = std::max(extent, bx.hi[i] - bx.lo[i]);
  // An eighth of the box: nearer than that, the box is a poor stand-in.
  double margin = 0.125 * extent;
  ir::NodeId id = b.make(ir::Kind::Bounded, {bx.lo[0], bx.lo[1], bx.lo[2], bx.hi[0], bx.hi[1], bx.hi[2], margin},
                         {child}, c.loc);
  ir::Props p = c.props;
  p.cost += 16;
  // The child divides itself by its L where it is corrected; the wrapper
  // sees a bound with L = 1 and must not divide again.
  if (p.corrected) p.lipschitz = 1, p.cls = ir::DistanceClass::Bound;
  p.corrected = false;
  p.lipschitz_region = ir::Box3::everything();
  b.graph().mutable_node(id).props = p;
  return id;
}

}  // namespace

ir::Module insert_bounding_volumes(ir::Module m) {
  m = detail::rewrite(std::move(m), [](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    if (n.kind == ir::Kind::Union || n.kind == ir::Kind::SmoothUnion)
      for (auto& k : kids)
        if (worth_bounding(b.graph().node(k))) k = wrap(b, k);
    ir::NodeId id = b.copy(n, std::move(kids));
    b.graph().mutable_node(id).props = n.props;
    return id;
  });
  // The root too: normals, shadows and AO rays evaluate the whole scene.
  ir::Builder b(*m.graph);
  if (worth_bounding(m.graph->node(m.root))) m.root = wrap(b, m.root);
  return m;
}

}  // namespace sdfc::passes
