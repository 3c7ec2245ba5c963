// Object sets' numbers in the kernel: the scene data buffer behind the frame
// block, and the prelude that passes it to every scene function. The walk
// itself is the object_set kind's (kinds/object_set.cpp).
#include "object_set_emitter.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "sdfc/ir/object_set.hpp"

namespace sdfc::codegen::detail {

namespace os = ir::object_set;

std::vector<float> scene_data(const ir::Module& m) {
  std::vector<float> data;
  if (m.root == ir::kNoNode) return data;
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (n.kind != ir::Kind::ObjectSet) continue;
    const os::View v{n.params};
    if (data.size() < v.offset() + v.floats()) data.resize(v.offset() + v.floats());
    std::transform(n.params.begin() + os::kHeader, n.params.end(), data.begin() + long(v.offset()),
                   [](double x) { return static_cast<float>(x); });
  }
  return data;
}

bool has_object_sets(const ir::Module& m) {
  if (m.root == ir::kNoNode) return false;
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (m.graph->node(id).kind == ir::Kind::ObjectSet) return true;
  return false;
}

bool camera_cones(const ir::Module& m) {
  const ir::Effects& fx = m.plan.effects;
  return has_object_sets(m) && m.plan.transport.integrator == ir::Transport::Integrator::Direct &&
         m.plan.camera.aperture == 0 &&
         m.plan.march.refine != ir::MarchSettings::Refine::Bisection && !fx.glow.enabled &&
         !(fx.ambient_occlusion.enabled && fx.ambient_occlusion.method == ir::AmbientOcclusion::Method::StepCount);
}

std::string scene_data_macros(bool animated, int unlocked) {
  std::string time = unlocked > 0 ? "const scalar time, __global const float* unlocked," : animated ? "const scalar time," : "";
  std::string arg = unlocked > 0 ? "time, unlocked," : animated ? "time," : "";
  return fmt::format(
      "// object sets read their numbers from scene_data, after the frame block: it follows the time in every "
      "function that evaluates the scene\n#undef TIME_PARAM\n#undef TIME_ARG\n#define TIME_PARAM {} __global const "
      "float* scene_data,\n#define TIME_ARG {} scene_data,\n",
      time, arg);
}

}  // namespace sdfc::codegen::detail
