#include "sdfc/reference/at_time.hpp"

namespace sdfc::reference {

ir::Module at_time(const ir::Module& m, double time) {
  ir::Module out = m;
  out.graph = std::make_shared<ir::Graph>(*m.graph);
  ir::Graph& g = *out.graph;
  for (auto& e : g.expressions) e = expr::substitute(e, "time", time);
  for (ir::NodeId id : g.postorder(out.root)) {
    ir::Node& n = g.mutable_node(id);
    for (size_t i = 0; i < n.anim.size(); ++i)
      if (n.anim[i]) n.params[i] = expr::evaluate(n.anim[i], {{"time", time}});
    n.anim.clear();
  }
  return out;
}

}  // namespace sdfc::reference
