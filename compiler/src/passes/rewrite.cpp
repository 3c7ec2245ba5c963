#include "rewrite.hpp"

namespace sdfc::passes::detail {

ir::Module rewrite(ir::Module m, const Rule& rule) {
  auto fresh = std::make_shared<ir::Graph>();
  fresh->expressions = m.graph->expressions;
  const std::vector<ir::NodeId> order = m.graph->postorder(m.root);
  ir::Builder b(*fresh);
  // Indexed by old id: a hash map cost an allocation and a lookup per node.
  std::vector<ir::NodeId> mapped(m.graph->size(), ir::kNoNode);
  for (ir::NodeId id : order) {
    const ir::Node& n = m.graph->node(id);
    std::vector<ir::NodeId> kids;
    kids.reserve(n.children.size());
    for (ir::NodeId c : n.children) kids.push_back(mapped[c]);
    mapped[id] = rule(b, n, std::move(kids));
  }
  if (m.root != ir::kNoNode) m.root = mapped[m.root];
  m.graph = std::move(fresh);
  return m;
}

}  // namespace sdfc::passes::detail
