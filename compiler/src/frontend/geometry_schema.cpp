#include "sdfc/frontend/geometry_schema.hpp"

#include <fmt/format.h>

#include "sdfc/ir/de_info.hpp"

#include <cmath>
#include <algorithm>

#include "animated_node.hpp"
#include "domain_schema.hpp"
#include "rotation_matrix.hpp"
#include "sdfc/formula/preset.hpp"
#include "sdfc/kinds/lowering.hpp"
#include "sdfc/kinds/registry.hpp"
#include "too_small.hpp"

namespace sdfc::frontend {

using ir::Kind;
using ir::NodeId;

const std::vector<std::string_view>& geometry_kinds() {
  // In the order "did you mean" has always tried them (it keeps the first
  // of equally close words): the first six primitives, the combinators, the
  // fractals, the other described kinds, segment, the blends.
  static const std::vector<std::string_view> combinators = {
      "union", "intersection", "difference", "smooth_union", "smooth_intersection", "smooth_difference"};
  static const std::vector<std::string_view> all = [] {
    std::vector<std::string_view> v;
    for (const kinds::Description* d : kinds::all())
      if (d->kind <= Kind::Capsule) v.push_back(d->yaml);
    v.insert(v.end(), combinators.begin(), combinators.end());
    auto fractal = [](const kinds::Description* d) { return ir::info(d->kind).category == ir::Category::Fractal; };
    for (const kinds::Description* d : kinds::all())  // the Juliabulb shares the mandelbulb's key
      if (fractal(d) && d->kind != Kind::Juliabulb) v.push_back(d->yaml);
    for (const kinds::Description* d : kinds::all())
      if (d->kind > Kind::Capsule && !fractal(d)) v.push_back(d->yaml);
    v.push_back("segment");  // a second spelling of the capsule
    v.insert(v.end(), blend_kinds().begin(), blend_kinds().end());
    for (const formula::Preset* p : formula::presets())  // presets not named like a built-in kind
      if (!kinds::find(p->name)) v.push_back(p->name);
    return v;
  }();
  return all;
}

const std::vector<std::string_view>& geometry_modifiers() {
  static const std::vector<std::string_view> k = [] {
    std::vector<std::string_view> v = domain_modifiers();
    v.insert(v.end(), {"scale", "rotate", "translate", "material", "step_factor"});
    return v;
  }();
  return k;
}

namespace {

bool contains(const std::vector<std::string_view>& v, std::string_view s) {
  for (auto x : v)
    if (x == s) return true;
  return false;
}

}  // namespace

NodeId GeometryLowering::lower(const SourceValue& v) {
  if (!v.is_map()) {
    r_.sink().error(v.loc, "expected a geometry node (a map such as '{sphere: {radius: 1}}'), got " + v.kind_name(),
                    v.is_seq() ? "to combine several shapes, list them under 'union:'" : "");
    return ir::kNoNode;
  }
  const SourceValue* kind_key = nullptr;
  const SourceValue* body = nullptr;
  const auto& modifiers = geometry_modifiers();
  for (const auto& [k, val] : v.entries) {
    if (contains(modifiers, k.scalar)) continue;
    if (contains(geometry_kinds(), k.scalar)) {
      if (kind_key) {
        // A --set that names a kind the node does not have adds it beside the
        // node's own: say how the path should continue instead.
        const SourceValue& added = k.loc.file && k.loc.file->rfind("--set", 0) == 0 ? k : *kind_key;
        const SourceValue& own = &added == &k ? *kind_key : k;
        bool from_set = added.loc.file && added.loc.file->rfind("--set", 0) == 0;
        r_.sink().error(k.loc, fmt::format("a geometry node has one kind, but this one has '{}' and '{}'",
                                           kind_key->scalar, k.scalar),
                        from_set ? fmt::format("this node is a '{}' in the scene file: a --set path follows the file's "
                                               "keys through it{}",
                                               own.scalar, own.scalar == "union"
                                                               ? fmt::format(" (its first child: scene.union.0.{}...)", added.scalar)
                                                               : std::string())
                                 : std::string("put them in a union: '{union: [...]}'"));
        return ir::kNoNode;
      }
      kind_key = &k;
      body = &val;
      continue;
    }
    std::vector<std::string_view> all = geometry_kinds();
    all.insert(all.end(), modifiers.begin(), modifiers.end());
    std::string hint = did_you_mean(k.scalar, all);
    if (hint.empty()) hint = "kinds: sphere, box, torus, plane, cylinder, capsule, mandelbulb, union, ...";
    r_.sink().error(k.loc, fmt::format("unknown node kind '{}'", k.scalar), hint);
    return ir::kNoNode;
  }
  if (!kind_key) {
    r_.sink().error(v.loc, "this geometry node has modifiers but no kind", "add a kind such as 'sphere: {radius: 1}'");
    return ir::kNoNode;
  }
  NodeId n = lower_kind(*kind_key, *body);
  if (n == ir::kNoNode) return n;
  return apply_modifiers(v, n);
}

NodeId GeometryLowering::lower_kind(const SourceValue& key, const SourceValue& body) {
  const std::string& k = key.scalar;
  const SourceLoc& at = key.loc;
  std::string what = k;
  // Blends other than the polynomial smooth ones (domain_schema.cpp).
  auto kids_of = [&](Kind kind, const SourceValue& list, std::vector<Param> params) {
    return lower_children(kind, key, list, std::move(params));
  };
  if (auto n = lower_blend(r_, key, body, kids_of)) return *n;
  // Combinators.
  if (k == "union" || k == "intersection" || k == "difference") {
    Kind kind = k == "union" ? Kind::Union : k == "intersection" ? Kind::Intersection : Kind::Difference;
    return lower_children(kind, key, body, {});
  }
  if (k == "smooth_union" || k == "smooth_intersection" || k == "smooth_difference") {
    MapReader m(r_, body, what, {"radius", "kind", "children"});
    if (!m.ok()) return ir::kNoNode;
    Param radius = m.require("radius") ? m.param("radius", 0.1, Range::positive()) : Param(0.1);
    const SourceValue* kids = m.require("children");
    if (!kids) return ir::kNoNode;
    Kind kind = k == "smooth_union" ? Kind::SmoothUnion : k == "smooth_intersection" ? Kind::SmoothIntersection : Kind::SmoothDifference;
    return lower_children(kind, key, *kids, {radius});
  }
  // Primitives (sdfc/kinds/ describes them) and fractals.
  if (k == "segment") {
    // A segment with a radius is the capsule's shape; it shares its node.
    MapReader m(r_, body, what, {"a", "b", "radius"});
    Vec3d a = m.vec3("a", {0, 0, -0.5}), bb = m.vec3("b", {0, 0, 0.5});
    double radius = m.number("radius", 0.1, Range::positive());
    return b_.make(Kind::Capsule, {a[0], a[1], a[2], bb[0], bb[1], bb[2], radius}, {}, at);
  }
  const kinds::Description* d = kinds::find(std::string_view(k));
  if (!d && formula::find_preset(k)) d = kinds::find(Kind::Formula);  // a preset's own node
  if (d) {
    kinds::Lowering l(*d, r_, b_, key, body);
    return d->lower(l);
  }
  r_.sink().error(at, fmt::format("unknown node kind '{}'", k), did_you_mean(k, geometry_kinds()));
  return ir::kNoNode;
}

NodeId GeometryLowering::lower_children(Kind kind, const SourceValue& key, const SourceValue& list,
                                        std::vector<Param> params) {
  std::string what(ir::info(kind).name);
  if (!list.is_seq()) {
    r_.sink().error(list.loc, fmt::format("{}: expected a list of geometry nodes, got {}", what, list.kind_name()), "");
    return ir::kNoNode;
  }
  if (list.items.empty()) {
    r_.sink().error(list.loc, fmt::format("{}: the list is empty", what), "give it at least one geometry node");
    return ir::kNoNode;
  }
  std::vector<NodeId> kids;
  bool bad = false;
  for (const auto& item : list.items) {
    NodeId c = lower(item);
    bad = bad || c == ir::kNoNode;
    kids.push_back(c);
  }
  if (bad) return ir::kNoNode;
  return make_node(b_, kind, params, std::move(kids), key.loc);
}

NodeId GeometryLowering::apply_modifiers(const SourceValue& node, NodeId n) {
  // Modifiers apply scale, then rotate, then translate, whatever their order
  // in the file: p_world = T(R(S(p_local))). Domain operations come first,
  // in the order of domain_modifiers().
  const NodeId base = n;
  n = apply_domain_modifiers(r_, b_, node, n);
  if (const SourceValue* s = node.find("scale"); s && s->is_seq()) {
    // Non-uniform: the distance is corrected by the smallest factor (a bound).
    Vec3d f = r_.vec3(*s, "scale", {0, 1e4, true});
    if (std::min({f[0], f[1], f[2]}) < kMinScale) too_small(r_, *s, "scale", std::min({f[0], f[1], f[2]}), kMinScale);
    n = b_.make(Kind::ScaleXYZ, {f[0], f[1], f[2]}, {n}, s->loc);
  } else if (s) {
    Param f = r_.param(*s, "scale", {0, 1e4, true});
    if (f.lo > 0 && f.lo < kMinScale) too_small(r_, *s, "scale", f.lo, kMinScale);
    n = make_node(b_, Kind::Scale, {f}, {n}, s->loc);
  }
  if (const SourceValue* rot = node.find("rotate")) {
    // Animated angles may grow without limit ("20*time"); static ones are checked.
    Range angles = Range::closed(-36000, 36000);
    std::array<Vec3d, 3> axes;
    Param3 deg{0.0, 0.0, 0.0};
    std::array<const SourceValue*, 3> where{rot, rot, rot};
    int count = 3;
    if (rot->is_scalar()) {  // a bare angle: say both forms, not only "a map"
      r_.sink().error(rot->loc,
                      fmt::format("rotate: expected {{axis: [x, y, z], degrees: a}} or a list [rx, ry, rz] of degrees about "
                                  "X, Y and Z, got '{}'", rot->scalar),
                      fmt::format("for {} degrees about the z axis: rotate: {{axis: [0, 0, 1], degrees: {}}}", rot->scalar,
                                  rot->scalar));
      return n;
    }
    if (rot->is_seq()) {
      // Degrees about X, then Y, then Z: R = Rz * Ry * Rx.
      axes = {Vec3d{0, 0, 1}, Vec3d{0, 1, 0}, Vec3d{1, 0, 0}};
      Param3 e = r_.param3(*rot, "rotate", {-1e300, 1e300});
      deg = {e[2], e[1], e[0]};
      if (rot->items.size() == 3) where = {&rot->items[2], &rot->items[1], &rot->items[0]};
    } else {
      MapReader mr(r_, *rot, "rotate", {"axis", "degrees"});
      axes[0] = mr.require("axis") ? mr.direction("axis", {0, 0, 1}) : Vec3d{0, 0, 1};
      deg[0] = mr.require("degrees") ? mr.param("degrees", 0, {-1e300, 1e300}) : Param(0.0);
      if (mr.get("degrees")) where[0] = mr.get("degrees");
      count = 1;
    }
    bool animated = false;
    for (int i = 0; i < count; ++i) {
      animated = animated || deg[i].animated();
      if (!deg[i].animated() && (deg[i].value < angles.lo || deg[i].value > angles.hi))
        r_.sink().error(where[i]->loc, fmt::format("{}: expected a number from -36000 to 36000, got {}",
                                                   rot->is_seq() ? "rotate" : "rotate.degrees", where[i]->scalar), "");
    }
    if (!animated) {
      std::array<double, 9> m = rotation_matrix(axes, deg, count);
      n = b_.make(Kind::Rotate, std::vector<double>(m.begin(), m.end()), {n}, rot->loc);
    } else {
      n = make_node(b_, Kind::Rotate, animated_rotation(axes, deg, count), {n}, rot->loc);
    }
  }
  if (const SourceValue* t = node.find("translate")) {
    Param3 v = r_.param3(*t, "translate");
    n = make_node(b_, Kind::Translate, {v[0], v[1], v[2]}, {n}, t->loc);
  }
  if (const SourceValue* f = node.find("step_factor")) {
    // The fudge factor, local to this node: its distance times f.
    double factor = r_.number(*f, "step_factor", {0, 2, true});
    n = b_.make(Kind::StepFactor, {factor}, {n}, f->loc);
  } else if (base != ir::kNoNode) {
    // A fractal whose estimator measurably overshoots gets its measured
    // default (ir::default_step_factor), at the node's own line.
    const ir::Node& bn = b_.graph().node(base);
    double factor = ir::default_step_factor(bn);
    if (factor != 1.0) n = b_.make(Kind::StepFactor, {factor}, {n}, bn.loc);
  }
  if (const SourceValue* mat = node.find("material")) {
    if (!mat->is_scalar()) {
      r_.sink().error(mat->loc, "material: expected a material name, got " + mat->kind_name(), "");
      return n;
    }
    std::vector<std::string_view> names;
    for (size_t i = 1; i < plan_.materials.size(); ++i) {
      names.push_back(plan_.materials[i].name);
      if (plan_.materials[i].name == mat->scalar) return b_.make(Kind::Material, {double(i)}, {n}, mat->loc);
    }
    std::string hint = did_you_mean(mat->scalar, names);
    if (hint.empty()) hint = names.empty() ? "the scene defines no materials" : "define it under 'materials:'";
    r_.sink().error(mat->loc, fmt::format("unknown material '{}'", mat->scalar), hint);
  }
  return n;
}

}  // namespace sdfc::frontend
