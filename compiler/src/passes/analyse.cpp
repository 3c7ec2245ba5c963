// analyse: records on the module what the emitters need to know about the
// whole scene (ir::Analyses): whether it uses time, whether smooth blends
// mix materials, whether any material has an orbit trap, the one material
// of a single-material scene, and where rays march. It runs after
// infer_properties, whose bounds it reuses, and before
// insert_bounding_volumes, which wraps subtrees in box tests without
// changing any of these facts (they name no node).
#include <algorithm>
#include <map>
#include <set>

#include "fit_box.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/ir/analyses.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace {

using ir::Kind;
using ir::NodeId;

bool uses_time(const ir::Module& m) {
  if (m.graph->animated(m.root) || m.plan.effects.fog.density_anim) return true;
  for (const auto& l : m.plan.lights)
    if (l.intensity_anim || l.position_anim[0] || l.position_anim[1] || l.position_anim[2]) return true;
  return false;
}

bool orbit_traps(const ir::RenderPlan& plan) {
  return std::any_of(plan.materials.begin(), plan.materials.end(), [](const auto& md) { return md.orbit_coloured(); });
}

// Smooth blends whose children's materials are mixed by the blend weight
// (their description's op_weight_* function): the polynomial smooth
// operations and the cubic and exponential blends.
bool mixes_materials(const ir::Node& n) {
  const kinds::Description* d = kinds::operation(n.kind);
  return d && d->weight && !d->weight(n).empty();
}

// The materials a subtree shows, as keys: the material id, or for a
// material with an orbit-trap palette one key per leaf (each leaf has its own
// trap, so two leaves of one such material still differ). Sets `blend` when
// a smooth blend's children show more than one key.
class BlendFinder {
 public:
  explicit BlendFinder(const ir::Module& m) : g_(*m.graph), plan_(m.plan) {}
  bool found(NodeId root) {
    keys(root, 0);
    return blend_;
  }

 private:
  std::set<long> keys(NodeId id, double mat) {
    auto memo = memo_.find({id, mat});
    if (memo != memo_.end()) return memo->second;
    const ir::Node& n = g_.node(id);
    std::set<long> out;
    if (n.kind == Kind::Material) mat = kinds::material_id(n);
    if (n.children.empty()) {
      bool trap = plan_.materials.at(size_t(mat)).orbit_coloured();
      out.insert(trap ? -1 - long(id) : long(mat));
    }
    for (NodeId c : n.children) {
      std::set<long> k = keys(c, mat);
      out.insert(k.begin(), k.end());
    }
    if (mixes_materials(n) && out.size() > 1) blend_ = true;
    memo_.emplace(std::make_pair(id, mat), out);
    return out;
  }

  const ir::Graph& g_;
  const ir::RenderPlan& plan_;
  bool blend_ = false;
  std::map<std::pair<NodeId, double>, std::set<long>> memo_;
};

// The material id of every hit when the whole scene carries one material
// (the root, looking through bounding boxes, is a material node and no other
// material node is reachable): then the hit needs no scene_dist_mat call.
std::optional<double> uniform_material(const ir::Module& m) {
  const ir::Graph& g = *m.graph;
  NodeId id = m.root;
  while (g.node(id).kind == Kind::Bounded) id = g.node(id).children[0];
  if (g.node(id).kind != Kind::Material) return std::nullopt;
  int materials = 0;
  for (NodeId n : g.postorder(m.root)) materials += g.node(n).kind == Kind::Material;
  if (materials != 1) return std::nullopt;
  return kinds::material_id(g.node(id));
}

// Where rays march: the scene's inferred bounds padded by 1% of their size
// plus a little, since the hit test accepts points up to an epsilon outside
// the surface; and for a lone Mandelbulb or Juliabulb (through bounding boxes
// and its material) the ball of its set radius, the half extent of the cube
// infer_properties gave it, padded the same way, which cuts the box's
// corners off primary and shadow rays. None for an unbounded scene.
std::optional<ir::RayBounds> ray_bounds(const ir::Module& m) {
  const ir::Graph& g = *m.graph;
  const ir::Props& root = g.node(m.root).props;
  if (!root.bounds.finite()) return std::nullopt;
  double ext = 0;
  for (int i = 0; i < 3; ++i) ext = std::max(ext, root.bounds.hi[i] - root.bounds.lo[i]);
  ir::RayBounds b;
  b.box = root.bounds.padded(0.01 * ext + 1e-3);
  NodeId id = m.root;
  while (g.node(id).kind == Kind::Bounded || g.node(id).kind == Kind::Material) id = g.node(id).children[0];
  const ir::Node& n = g.node(id);
  const kinds::Description* d = kinds::find(n.kind);
  double radius = d && d->ball_bounds ? n.props.bounds.hi[0] : 0;
  if (radius > 0) {
    b.has_sphere = true;
    b.radius = radius * 1.01 + 1e-3;
  }
  return b;
}

// For an unbounded scene: a plain union (through bounding boxes and
// materials) whose children are planes or have finite bounds, at least one
// of each. The box is padded as ray_bounds pads the scene's.
std::optional<ir::ShadowBounds> shadow_bounds(const ir::Module& m) {
  const ir::Graph& g = *m.graph;
  auto unwrap = [&](NodeId id) {
    while (g.node(id).kind == Kind::Bounded || g.node(id).kind == Kind::Material) id = g.node(id).children[0];
    return id;
  };
  const ir::Node& u = g.node(unwrap(m.root));
  if (u.kind != Kind::Union) return std::nullopt;
  ir::ShadowBounds s;
  bool any_box = false;
  for (NodeId c : u.children) {
    const ir::Node& n = g.node(unwrap(c));
    if (n.kind == Kind::Plane) {
      s.plane_normals.push_back({n.params[0], n.params[1], n.params[2]});  // fixed and unit (the plane kind's reader)
      continue;
    }
    const ir::Box3& b = g.node(c).props.bounds;
    if (!b.finite()) return std::nullopt;
    s.box = any_box ? s.box.united(b) : b;
    any_box = true;
  }
  if (!any_box || s.plane_normals.empty()) return std::nullopt;
  double ext = 0;
  for (int i = 0; i < 3; ++i) ext = std::max(ext, s.box.hi[i] - s.box.lo[i]);
  s.box = s.box.padded(0.01 * ext + 1e-3);
  return s;
}

}  // namespace

ir::Module analyse(ir::Module m) {
  ir::Analyses a;
  a.known = true;
  a.uses_time = uses_time(m);
  a.material_blend = BlendFinder(m).found(m.root);
  a.orbit_traps = orbit_traps(m.plan);
  a.coloring_geometry = std::any_of(m.plan.materials.begin(), m.plan.materials.end(),
                                    [](const auto& md) { return md.geometry_coloured(); });
  a.uniform_material = uniform_material(m);
  a.ray_bounds = ray_bounds(m);
  if (!a.ray_bounds) a.shadow_bounds = shadow_bounds(m);
  m.analyses = std::move(a);
  detail::record_fit_box(m);  // what camera.fit frames
  return m;
}

}  // namespace sdfc::passes
