// verify: the structural invariants every later stage relies on. A failure
// here is a compiler bug, so it throws std::logic_error, not a SceneError.
#include <cmath>
#include <stdexcept>
#include <string>

#include "sdfc/passes/passes.hpp"
#include "sdfc/kinds/params.hpp"

namespace sdfc::passes {

ir::Module verify(ir::Module m) {
  auto fail = [](const std::string& why) { throw std::logic_error("IR verification failed: " + why); };
  if (m.root == ir::kNoNode) fail("no root");
  if (m.root >= m.graph->size()) fail("root out of range");
  if (m.plan.materials.empty()) fail("no default material");
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    const ir::KindInfo& k = ir::info(n.kind);
    std::string where = "%" + std::to_string(id) + " (" + std::string(k.name) + ")";
    const bool data = n.kind == ir::Kind::ObjectSet;  // a header, then its data
    if (data ? n.params.size() < k.params.size() : n.params.size() != k.params.size()) fail(where + ": parameter count");
    for (double p : n.params)
      if (!std::isfinite(p)) fail(where + ": non-finite parameter");
    if (k.arity == 0 && !n.children.empty()) fail(where + ": a leaf with children");
    if (k.arity == 1 && n.children.size() != 1) fail(where + ": needs exactly one child");
    if (k.arity == -1 && n.children.empty()) fail(where + ": combinator without children");
    for (ir::NodeId c : n.children)
      if (c >= m.graph->size()) fail(where + ": child out of range");
    if (n.kind == ir::Kind::Material && (kinds::material_id(n) < 0 || size_t(kinds::material_id(n)) >= m.plan.materials.size()))
      fail(where + ": material id out of range");
  }
  return m;
}

}  // namespace sdfc::passes
