// object_set: inserted by the gather_object_sets pass, never written by
// users. A large union of spheres and boxes held as data
// (sdfc/ir/object_set.hpp): one call of the stdlib's hierarchy walk
// (os_union, stdlib/object_set.cl), its numbers read from the scene data
// buffer, so the kernel source is the same size for ten objects or ten thousand.
#include "domain_op.hpp"
#include "../reference/object_set.hpp"
#include "sdfc/ir/object_set.hpp"

SDFC_KIND(ObjectSet,          56, "object_set",          Combinator, 0, "offset,nodes,items,primitives", "os_union")

namespace sdfc::kinds {
namespace {
using namespace domain;
namespace os = ir::object_set;

struct ObjectSetP {  // the header; the data follows it
  double offset, nodes, items, primitives;
};

// The pass computes a set's properties (bounds, and the cost of its walk
// where it does the most work) when it makes the node.
ir::Props props(const ir::Graph&, const ir::Node& n, const Kid&) { return n.props; }

Sample evaluate(const ir::Graph&, const ir::Node& n, const V3& p) { return reference::detail::object_set_evaluate(n, p); }

// scene_material: the record of the nearest item's material `id`, as
// material_of gives it, with that material's reflectivity.
std::string record(Walker& w, const std::string& id) {
  const ir::Module& m = w.module();
  const codegen::detail::Literals& lit = w.lit();
  w.call("mat_record");
  std::string rec = w.var("r");
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

Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  const os::View v{n.params};
  std::string d = w.var("d"), mat = w.var("m");
  w.line(fmt::format("real {};  // object set: {} items, {} primitives, {} hierarchy nodes as data{}", mat, v.items(),
                     v.prims(), v.nodes(), w.where(n)));
  const std::string bound = !w.cull_bound.empty() ? w.cull_bound : !w.above.empty() ? w.above : w.lit().typed(1e30);
  w.line(fmt::format("real {} = {}({}, scene_data + {}, {}, {}, {}, {}, {}, &{});", d, w.call("os_union"), p,
                     v.offset(), v.nodes(), v.items(), bound, w.live_lanes, w.cone, mat));
  if (w.tracks_trap()) return {d, w.lit().typed(0)};  // no fractal inside: no trap
  if (!w.carries_records()) return {d, w.tracks_material() ? mat : ""};
  std::string id = w.var("m");  // items without a material of their own show the one above the set
  w.line(fmt::format("real {} = SEL({}, {}, {} != 0.0f);", id, w.lit().typed(w.material()), mat, mat));
  return {d, id, record(w, id)};
}

}  // namespace

namespace described {
extern const Description ObjectSet{.kind = ir::Kind::ObjectSet,
                                   .yaml = "object_set",
                                   .param_count = count_of<ObjectSetP>(),
                                   .child_props = props,
                                   .evaluate = evaluate,
                                   .walk = walk};
}

}  // namespace sdfc::kinds
