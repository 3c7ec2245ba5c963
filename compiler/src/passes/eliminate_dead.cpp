// eliminate_dead: materials no reachable node uses and lights that add no
// light are removed from the plan, so the kernel holds no code for them.
// Material ids are renumbered densely (0 stays the default material).
#include <map>

#include "rewrite.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

ir::Module eliminate_dead(ir::Module m) {
  std::map<int, int> remap{{0, 0}};
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (n.kind == ir::Kind::Material) remap.emplace(kinds::material_id(n), 0);
  }
  std::vector<ir::MaterialDef> kept;
  for (auto& [old_id, new_id] : remap) {
    new_id = int(kept.size());
    kept.push_back(m.plan.materials.at(old_id));
  }
  m.plan.materials = std::move(kept);
  m = detail::rewrite(std::move(m), [&remap](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    if (n.kind != ir::Kind::Material) return b.copy(n, std::move(kids));
    return b.make(n.kind, {double(remap.at(kinds::material_id(n)))}, std::move(kids), n.loc);
  });

  std::vector<ir::Light> lit;
  for (const auto& l : m.plan.lights) {
    bool dark = (l.intensity <= 0 && !l.intensity_anim) || (l.color[0] <= 0 && l.color[1] <= 0 && l.color[2] <= 0);
    if (!dark) lit.push_back(l);
  }
  m.plan.lights = std::move(lit);
  return m;
}

}  // namespace sdfc::passes
