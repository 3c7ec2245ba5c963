#include "rewrite.hpp"

#include <unordered_map>

namespace sdfc::passes::detail {

ir::Module rewrite(ir::Module m, const Rule& rule) {
  auto fresh = std::make_shared<ir::Graph>();
  fresh->expressions = m.graph->expressions;
  ir::Builder b(*fresh);
  std::unordered_map<ir::NodeId, ir::NodeId> mapped;
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    std::vector<ir::NodeId> kids;
    kids.reserve(n.children.size());
    for (ir::NodeId c : n.children) kids.push_back(mapped.at(c));
    mapped[id] = rule(b, n, std::move(kids));
  }
  if (m.root != ir::kNoNode) m.root = mapped.at(m.root);
  m.graph = std::move(fresh);
  return m;
}

}  // namespace sdfc::passes::detail
