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

bool passes_cone(ir::Kind k) {
  return k == ir::Kind::Union || k == ir::Kind::Bounded || k == ir::Kind::Material || k == ir::Kind::ObjectSet;
}

namespace {
// Whether some object set is reached from the root through nodes that pass the cone on.
bool cone_reaches_a_set(const ir::Graph& g, ir::NodeId id) {
  const ir::Node& n = g.node(id);
  if (n.kind == ir::Kind::ObjectSet) return true;
  if (!passes_cone(n.kind)) return false;
  return std::any_of(n.children.begin(), n.children.end(), [&](ir::NodeId c) { return cone_reaches_a_set(g, c); });
}
}  // namespace

bool camera_cones(const ir::Module& m) {
  const ir::Effects& fx = m.plan.effects;
  return has_object_sets(m) && cone_reaches_a_set(*m.graph, m.root) && m.plan.transport.integrator == ir::Transport::Integrator::Direct &&
         m.plan.camera.aperture == 0 &&
         m.plan.march.refine != ir::MarchSettings::Refine::Bisection && !fx.glow.enabled &&
         !(fx.ambient_occlusion.enabled && fx.ambient_occlusion.method == ir::AmbientOcclusion::Method::StepCount);
}

ir::NodeId top_of_scene(const ir::Module& m) {
  const ir::Node& root = m.graph->node(m.root);
  return root.kind == ir::Kind::Bounded && !root.props.corrected ? root.children[0] : m.root;
}

bool bounded_normals(const ir::Module& m) {
  if (m.root == ir::kNoNode) return false;
  const ir::Graph& g = *m.graph;
  const ir::Node& root = g.node(top_of_scene(m));
  if (root.props.corrected) return false;
  auto plain_set = [&](ir::NodeId id) {  // spheres, boxes and polynomial blends: 1-Lipschitz
    const ir::Node& n = g.node(id);
    return n.kind == ir::Kind::ObjectSet && !n.props.corrected;
  };
  auto exact = [&](ir::NodeId id) {  // a Euclidean distance all through: 1-Lipschitz
    for (ir::NodeId k : g.postorder(id))
      if (g.node(k).props.cls != ir::DistanceClass::Exact || g.node(k).props.corrected) return false;
    return true;
  };
  if (plain_set(top_of_scene(m))) return true;
  if (root.kind != ir::Kind::Union || root.children.size() < 2 || !plain_set(root.children.back())) return false;
  return std::all_of(root.children.begin(), root.children.end() - 1, exact);
}

bool bounded_shading(const ir::Module& m) {
  return m.plan.march.normals != ir::NormalMethod::Dual && !m.analyses.material_blend && bounded_normals(m);
}

void emit_bounded_hit(CodeWriter& w, const ir::Module& m, const Literals& lit, std::set<std::string>& used,
                      const std::string& cone) {
  const char* normal_fn =
      m.plan.march.normals == ir::NormalMethod::Central ? "normal_central_below" : "normal_tetrahedral_below";
  used.insert(normal_fn);
  if (const auto& uni = m.analyses.uniform_material) {
    w.line(fmt::format("id = {};  // the scene's one material", lit.typed(*uni)));
    w.line(fmt::format("const real d_hit = scene_dist_below(TIME_ARG pos, K(1e30f), hit, {});", cone));
  } else {
    w.line(fmt::format("const real d_hit = scene_dist_mat_hit(TIME_ARG pos, hit, {}, &id);", cone));
  }
  w.line(fmt::format("n = {}(TIME_ARG pos, h, d_hit, hit, {});  // the taps are at most d_hit + their reach", normal_fn,
                     cone));
}

bool shading_from_list(const ir::Module& m) { return bounded_shading(m) && !camera_list_gather(m).empty(); }

std::string camera_list_gather(const ir::Module& m) {
  if (!camera_cones(m)) return "";
  const ir::Node* set = nullptr;
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(id);
    if (n.kind != ir::Kind::ObjectSet) continue;
    if (set) return "";  // one list per cone: the march would read it for every set
    set = &n;
  }
  const os::View v{set->params};
  return fmt::format("os_list_gather(&list, cone, scene_data + {}, {}, {}, scene_data + {});", v.offset(), v.nodes(),
                     v.items(), v.offset() + v.gather_at());
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
