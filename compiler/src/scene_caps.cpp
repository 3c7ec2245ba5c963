#include "sdfc/scene_caps.hpp"

#include <fmt/format.h>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc {

SceneCaps& scene_caps() {
  static SceneCaps caps;
  return caps;
}

double estimated_cost_per_sample(const ir::Module& m) {
  if (m.root == ir::kNoNode) return 0;
  const ir::RenderPlan& p = m.plan;
  double evaluations = p.march.max_steps + 7;  // the march, then the normal's six probes and the material
  for (const auto& l : p.lights)
    if (l.shadows != ir::Light::Shadows::None) evaluations += l.shadow_steps;
  if (p.effects.ambient_occlusion.enabled) evaluations += p.effects.ambient_occlusion.samples;
  if (p.transport.integrator == ir::Transport::Integrator::Path)
    evaluations *= 1 + p.transport.max_bounces;  // every bounce marches, shades and casts its shadow rays
  else
    evaluations *= 1 + p.effects.reflections.depth;
  return evaluations * m.graph->node(m.root).props.cost;
}

void check_scene_cost(const ir::Module& m) {
  const SceneCaps& caps = scene_caps();
  if (caps.allow_slow || m.root == ir::kNoNode) return;
  const double cost = estimated_cost_per_sample(m);
  if (!(cost <= caps.max_cost_per_sample))
    fail(m.graph->node(m.root).loc,
         fmt::format("the scene's estimated cost is {:.3g} operations per sample, over the limit of {:.3g} "
                     "(it would take far too long to render)",
                     cost, caps.max_cost_per_sample),
         "nested repeats multiply the work per level; pass --allow-slow to render it anyway");
}

}  // namespace sdfc
