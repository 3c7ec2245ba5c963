#include "scene_walker.hpp"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>
#include <utility>

#include "fractal_emitter.hpp"
#include "kernel_text.hpp"
#include "kind_call.hpp"
#include "object_set_emitter.hpp"
#include "trap_shape_emitter.hpp"
#include "sdfc/expr/expr.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::codegen::detail {

using ir::Kind;
using ir::NodeId;
using Value = kinds::Carried;
using kinds::with_d;

SceneWalker::SceneWalker(const ir::Module& m, const Literals& lit, std::set<std::string>& used, CodeWriter& w, Carry carry)
    : m_(m),
      g_(*m.graph),
      plan_(m.plan),
      lit_(lit),
      used_(used),
      w_(w),
      carry_(carry),
      orbit_traps_(m.analyses.orbit_traps),
      coloring_geometry_(m.analyses.coloring_geometry),
      file_(m.source_name) {
  if (carry == Carry::Trap || carry == Carry::Records) find_trap_sources(m, m.root, 0);
}

std::string SceneWalker::var(const char* prefix) { return fmt::format("{}{}", prefix, w_.fresh()); }

std::string SceneWalker::call(const std::string& fn) {
  used_.insert(fn);
  return fn;
}

double SceneWalker::enter_material(double id) { return std::exchange(cur_mat_, id); }

std::string SceneWalker::where(const ir::Node& n) const {
  if (n.loc.line <= 0) return "";
  std::string f = n.loc.file ? *n.loc.file : file_;
  size_t slash = f.find_last_of('/');
  if (slash != std::string::npos) f = f.substr(slash + 1);
  return fmt::format("  ({}:{})", kernel_text(f), n.loc.line);
}

std::string SceneWalker::describe(const ir::Node& n) const {
  const ir::KindInfo& k = ir::info(n.kind);
  std::string s(k.name);
  for (size_t i = 0; i < n.params.size() && n.kind != Kind::Rotate; ++i) {
    if (const auto& e = n.animation(i)) s += fmt::format(" {}=\"{}\"", k.params[i], kernel_text(expr::to_string(e)));
    else s += fmt::format(" {}={}", k.params[i], n.params[i]);
  }
  if (n.kind == Kind::Rotate && n.animated()) s += " (animated)";  // nine numbers say less than that
  return s + where(n);
}

Value SceneWalker::emit(NodeId id, const std::string& p) {
  const bool top = id == m_.root || id == top_of_scene(m_);  // the bound passes a bounding box at the root
  const std::string above = top ? this->above : std::exchange(this->above, "");
  const std::string cone = passes_cone(g_.node(id).kind) ? this->cone : std::exchange(this->cone, "os_cone_none()");
  Value v = emit_node(id, p);
  this->above = above;
  this->cone = cone;
  const ir::Node& n = g_.node(id);
  if (!n.props.corrected) return v;
  const ir::Box3& r = n.props.lipschitz_region;
  std::string d = var("d");
  std::string scaled = fmt::format("{} * {}", v.d, lit_.real(1.0 / n.props.lipschitz));
  if (!r.finite()) {
    w_.line(fmt::format("real {} = {};  // L = {:.4g} > 1: divide by L", d, scaled, n.props.lipschitz));
    return with_d(v, d);
  }
  // L holds inside the region only; outside it the distance to the node's
  // bounds is the bound (the surface lies inside them, at least the
  // region's margin away).
  std::string b = var("b"), o = var("o");
  call("dm_axis_helpers");
  w_.line(fmt::format("real {} = dm_box_outside({}, {}, {});  // L = {:.4g} > 1 inside this box", o, p, lit_.vec3(r.lo),
                      lit_.vec3(r.hi), n.props.lipschitz));
  w_.line(fmt::format("real {} = dm_box_outside({}, {}, {});  // the node's bounds", b, p, lit_.vec3(n.props.bounds.lo),
                      lit_.vec3(n.props.bounds.hi)));
  w_.line(fmt::format("real {} = SEL({}, {}, {} > 0.0f);  // divide by L inside, bounds distance outside", d, scaled, b, o));
  return with_d(v, d);
}

Value SceneWalker::emit_node(NodeId id, const std::string& p) {
  const ir::Node& n = g_.node(id);
  leaf_p_ = p;  // for record(): leaves do not recurse, so this is still theirs
  if (const kinds::Description* d = kinds::operation(n.kind)) return d->walk(*this, n, p);
  if (auto e = kind_call(n, p, lit_, used_)) return leaf(n, *e);
  if (is_fractal(n)) return fractal(id, n, p);
  throw std::logic_error(fmt::format("scene walker: kind '{}' has no description", ir::info(n.kind).name));
}

Value SceneWalker::leaf(const ir::Node& n, const std::string& expr) {
  std::string d = var("d");
  w_.line(fmt::format("real {} = {};  // {}", d, expr, describe(n)));
  if (carries_records()) return {d, lit_.typed(cur_mat_), record(n)};
  return {d, tracks_material() ? lit_.typed(0) : ""};
}

// A fractal's estimate; in scene_trap and scene_iterations also the orbit
// value its material asks for (trap, smooth count) or its escape count.
Value SceneWalker::fractal(NodeId id, const ir::Node& n, const std::string& p) {
  Value v = leaf(n, emit_fractal(n, p, lit_, w_, used_));
  const bool iterations = carry_ == Carry::Iterations;
  const OrbitValue value = iterations ? OrbitValue::Escape : iteration_.count(id) ? OrbitValue::Smooth : OrbitValue::Trap;
  std::optional<size_t> shape;
  if (auto it = shaped_.find(id); it != shaped_.end() && value == OrbitValue::Trap) shape = it->second;
  std::string trap = tracks_trap() ? emit_fractal_trap(n, p, lit_, w_, used_, value, shape) : "";
  if (!trap.empty()) {
    v.mat = var(iterations ? "it" : "trap");
    w_.line(fmt::format("real {} = {};  // {}", v.mat, trap,
                        iterations             ? "iteration count"
                        : iteration_.count(id) ? "smooth iteration count (its material's source)"
                                               : "orbit trap"));
  }
  return v;
}

// scene_material: the leaf's material (the nearest material node above it)
// as a record; an orbit-trap palette is applied here, with the leaf's own
// trap (0 for geometry without one), so blends mix finished colours.
std::string SceneWalker::record(const ir::Node& n) {
  const ir::MaterialDef& md = plan_.materials.at(size_t(cur_mat_));
  std::string rec = var("r");
  w_.line(fmt::format("mat_record {};  // material {} '{}'", rec, cur_mat_, kernel_text(md.name)));
  std::string trap;
  if (orbit_traps_) {
    trap = lit_.typed(0);
    if (md.orbit_coloured() && is_fractal(n)) {
      const bool iteration = md.trap_source == ir::MaterialDef::TrapSource::Iteration;
      std::optional<size_t> shape;
      if (!iteration && shaped_trap(plan_, size_t(cur_mat_))) shape = size_t(cur_mat_);
      std::string t = emit_fractal_trap(n, leaf_p_, lit_, w_, used_, iteration ? OrbitValue::Smooth : OrbitValue::Trap, shape);
      if (!t.empty()) trap = t;
    }
    trap = ", " + trap;
  }
  if (coloring_geometry_) trap += ", p, n";  // the world point and the normal scene_material takes
  w_.line(fmt::format("material_of({}, &{}.albedo, &{}.specular, &{}.shininess{});", lit_.typed(cur_mat_), rec, rec, rec,
                      trap));
  w_.line(fmt::format("{}.reflectivity = {};", rec, lit_.typed(md.reflectivity)));
  return rec;
}

// The nearest of the child over several points (one loop, the child's code once).
Value SceneWalker::cells(const ir::Node& n, const std::vector<std::string>& points) {
  const bool with_mat = tracks_material(), records = carries_records();
  std::string d = var("d"), m = with_mat ? var("m") : "", c = var("c"), rec = records ? var("r") : "";
  w_.line(fmt::format("real {} = {};", d, lit_.typed(1e30)));
  if (with_mat) w_.line(fmt::format("real {} = {};", m, lit_.typed(0)));
  if (records) w_.line(fmt::format("mat_record {} = mat_none();", rec));
  w_.open(fmt::format("for (int {0} = 0; {0} < {1}; ++{0}) {{", c, points.size()));
  std::string pc = var("p");
  std::string pick = points.back();
  for (size_t i = points.size() - 1; i-- > 0;) pick = fmt::format("{} == {} ? {} : {}", c, i, points[i], pick);
  w_.line(fmt::format("vec3 {} = {};", pc, pick));
  Value k = emit(n.children[0], pc);
  if (with_mat) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
  if (records) w_.line(fmt::format("{} = mat_select({}, {}, {} < {});", rec, rec, k.rec, k.d, d));
  w_.line(fmt::format("{} = fmin({}, {});", d, d, k.d));
  w_.close("}");
  return {d, m, rec};
}

// The fractals whose material (the nearest material above them, as for
// scene_dist_mat) colours by the smooth iteration count instead of the
// trap, and those whose material's trap has a shape.
void SceneWalker::find_trap_sources(const ir::Module& m, NodeId id, int material) {
  const ir::Node& n = g_.node(id);
  if (n.kind == Kind::Material) material = kinds::material_id(n);
  if (is_fractal(n) && material > 0 && size_t(material) < m.plan.materials.size() &&
      m.plan.materials[size_t(material)].trap_source == ir::MaterialDef::TrapSource::Iteration)
    iteration_.insert(id);
  if (is_fractal(n) && material > 0 && shaped_trap(m.plan, size_t(material))) shaped_[id] = size_t(material);
  for (NodeId c : n.children) find_trap_sources(m, c, material);
}

}  // namespace sdfc::codegen::detail
