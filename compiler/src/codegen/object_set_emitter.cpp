// Object sets in the kernel: one call of the stdlib's hierarchy walk per set
// (os_union, stdlib/object_set.cl), its numbers read from the scene data
// buffer, so the kernel source is the same size for ten objects or ten thousand.
#include "object_set_emitter.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "sdfc/ir/object_set.hpp"

namespace sdfc::codegen::detail {

namespace os = ir::object_set;

ObjectSetCode emit_object_set(const ir::Node& n, const std::string& p, const std::string& where, CodeWriter& w,
                              std::set<std::string>& used) {
  const os::View v{n.params};
  used.insert("os_union");
  ObjectSetCode c{fmt::format("d{}", w.fresh()), fmt::format("m{}", w.fresh())};
  w.line(fmt::format("real {};  // object set: {} items, {} primitives, {} hierarchy nodes as data{}", c.mat, v.items(),
                     v.prims(), v.nodes(), where));
  w.line(fmt::format("real {} = os_union({}, scene_data + {}, {}, {}, &{});", c.d, p, v.offset(), v.nodes(), v.items(),
                     c.mat));
  return c;
}

std::string object_set_record(const std::string& id, const ir::Module& m, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used) {
  used.insert("mat_record");
  std::string rec = fmt::format("r{}", w.fresh());
  std::string extra = m.analyses.orbit_traps ? ", " + lit.typed(0) : "";  // no fractal in a set: trap 0
  if (m.analyses.coloring_geometry) extra += ", p, n";
  w.line(fmt::format("mat_record {};  // the object set's nearest material", rec));
  w.line(fmt::format("material_of({}, &{}.albedo, &{}.specular, &{}.shininess{});", id, rec, rec, rec, extra));
  w.line(fmt::format("{}.reflectivity = {};", rec, lit.typed(0)));
  for (size_t i = 0; i < m.plan.materials.size(); ++i)
    if (m.plan.materials[i].reflectivity != 0)
      w.line(fmt::format("{0}.reflectivity = SEL({0}.reflectivity, {1}, {2} == {3});", rec,
                         lit.typed(m.plan.materials[i].reflectivity), id, lit.typed(double(i))));
  return rec;
}

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
