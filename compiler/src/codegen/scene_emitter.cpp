// Geometry to OpenCL C: one statement per IR node, each commented with the
// node and the YAML line it came from. Points flow down (transforms make new
// point variables), distances flow up.
#include "scene_emitter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "kind_call.hpp"
#include "fractal_emitter.hpp"
#include "kernel_text.hpp"
#include "object_set_emitter.hpp"
#include "trap_shape_emitter.hpp"
#include "sdfc/expr/expr.hpp"
#include "sdfc/ir/analyses.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;
using ir::NodeId;

struct Value {
  std::string d;    // distance variable
  std::string mat;  // material variable or real-typed literal; "" when not tracked
  std::string rec = "";  // blended material record (mat_record variable); scene_material only
};

// The same value with another distance (modifiers keep the material).
Value with_d(Value v, std::string d) {
  v.d = std::move(d);
  return v;
}

class SceneEmitter {
 public:
  // trap: emit scene_trap instead, where the tracked value is the orbit
  // trap of the nearest fractal (chosen by the same rules as the material).
  // blend: emit scene_material instead, which carries a material record
  // (mat_record) up the tree and mixes it at smooth blends.
  // iterations: scene_iterations, tracking the nearest fractal's iteration
  // count (the AOV) like scene_trap tracks its trap.
  SceneEmitter(const ir::Module& m, const Literals& lit, bool with_mat, std::set<std::string>& used, bool trap = false,
               bool blend = false, bool iterations = false)
      : g_(*m.graph),
        module_(m),
        plan_(m.plan),
        lit_(lit),
        with_mat_(with_mat || trap || blend || iterations),
        trap_(trap || iterations),
        blend_(blend),
        iterations_(iterations),
        used_(used),
        orbit_traps_(m.analyses.orbit_traps),
        coloring_geometry_(m.analyses.coloring_geometry),
        file_(m.source_name) {
    if (trap || blend) find_iteration_fractals(m, m.root, 0);
  }

  std::string function(NodeId root) {
    if (blend_) {
      call("mat_record");
      w_.line(coloring_geometry_ ? "real scene_material(TIME_PARAM vec3 p, vec3 n, mat_record* out)"
                                 : "real scene_material(TIME_PARAM vec3 p, mat_record* out)");
      w_.open("{");
      Value v = emit(root, "p");
      w_.line("(void)" + v.d + ";");
      w_.line("*out = " + v.rec + ";");
      w_.line("return " + v.mat + ";  // the nearest material's id (the material AOV)");
      w_.close("}");
      return w_.take();
    }
    w_.line(iterations_ ? "real scene_iterations(TIME_PARAM vec3 p)"
            : trap_     ? "real scene_trap(TIME_PARAM vec3 p)"
            : with_mat_ ? "real scene_dist_mat(TIME_PARAM vec3 p, real* mat)"
                        : "real scene_dist(TIME_PARAM vec3 p)");
    w_.open("{");
    Value v = emit(root, "p");
    if (trap_) {
      w_.line("(void)" + v.d + ";");
      w_.line("return " + v.mat + ";");
      w_.close("}");
      return w_.take();
    }
    if (with_mat_) w_.line("*mat = " + v.mat + ";");
    w_.line("return " + v.d + ";");
    w_.close("}");
    return w_.take();
  }

 private:
  std::string where(const ir::Node& n) const {
    if (n.loc.line <= 0) return "";
    std::string f = n.loc.file ? *n.loc.file : file_;
    size_t slash = f.find_last_of('/');
    if (slash != std::string::npos) f = f.substr(slash + 1);
    return fmt::format("  ({}:{})", kernel_text(f), n.loc.line);
  }

  std::string describe(const ir::Node& n) const {
    const ir::KindInfo& k = ir::info(n.kind);
    std::string s(k.name);
    for (size_t i = 0; i < n.params.size() && n.kind != Kind::Rotate; ++i) {
      if (const auto& e = n.animation(i)) s += fmt::format(" {}=\"{}\"", k.params[i], kernel_text(expr::to_string(e)));
      else s += fmt::format(" {}={}", k.params[i], n.params[i]);
    }
    if (n.kind == Kind::Rotate && n.animated()) s += " (animated)";
    return s + where(n);
  }

  std::string var(const char* prefix) { return fmt::format("{}{}", prefix, w_.fresh()); }

  std::string call(const std::string& fn) {
    used_.insert(fn);
    return fn;
  }

  Value leaf(const ir::Node& n, const std::string& expr) {
    std::string d = var("d");
    w_.line(fmt::format("real {} = {};  // {}", d, expr, describe(n)));
    if (blend_) return {d, lit_.typed(cur_mat_), record(n)};
    return {d, with_mat_ ? lit_.typed(0) : ""};
  }

  // scene_material: the leaf's material (the nearest material node above it)
  // as a record; an orbit-trap palette is applied here, with the leaf's own
  // trap (0 for geometry without one), so blends mix finished colours.
  std::string record(const ir::Node& n) {
    const ir::MaterialDef& md = plan_.materials.at(size_t(cur_mat_));
    const bool traps = orbit_traps_;
    std::string rec = var("r");
    w_.line(fmt::format("mat_record {};  // material {} '{}'", rec, cur_mat_, kernel_text(md.name)));
    std::string trap;
    if (traps) {
      trap = lit_.typed(0);
      if (md.orbit_coloured() && is_fractal(n)) {
        const bool iteration = md.trap_source == ir::MaterialDef::TrapSource::Iteration;
        std::optional<size_t> shape;
        if (!iteration && shaped_trap(plan_, size_t(cur_mat_))) shape = size_t(cur_mat_);
        std::string t =
            emit_fractal_trap(n, leaf_p_, lit_, w_, used_, iteration ? OrbitValue::Smooth : OrbitValue::Trap, shape);
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

  // A node's distance, divided by its Lipschitz constant where the
  // properties pass marked it for correction (issue 9).
  Value emit(NodeId id, const std::string& p) {
    Value v = emit_node(id, p);
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
    w_.line(fmt::format("real {} = dm_box_outside({}, {}, {});  // L = {:.4g} > 1 inside this box", o, p,
                        lit_.vec3(r.lo), lit_.vec3(r.hi), n.props.lipschitz));
    w_.line(fmt::format("real {} = dm_box_outside({}, {}, {});  // the node's bounds", b, p,
                        lit_.vec3(n.props.bounds.lo), lit_.vec3(n.props.bounds.hi)));
    w_.line(fmt::format("real {} = SEL({}, {}, {} > 0.0f);  // divide by L inside, bounds distance outside", d, scaled, b, o));
    return with_d(v, d);
  }

  Value emit_node(NodeId id, const std::string& p) {
    const ir::Node& n = g_.node(id);
    leaf_p_ = p;  // for record(): leaves do not recurse, so this is still theirs
    const auto& q = n.params;
    auto r = [&](size_t i) { return param(n, i, lit_); };
    auto v = [&](size_t i) { return param3(n, i, lit_); };
    switch (n.kind) {
      case Kind::Translate: {
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_sub({}, {});  // {}", p2, p, v(0), describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::Rotate: {
        // The node holds local->world; the point needs world->local, the transpose.
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {});  // {}", p2, p, r(0), r(3), r(6),
                            r(1), r(4), r(7), r(2), r(5), r(8), describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::Scale: {
        std::string p2 = var("p");
        std::string inv = n.animated() ? fmt::format("{} / {}", lit_.real(1.0), r(0)) : lit_.real(1.0 / q[0]);
        w_.line(fmt::format("vec3 {} = v3_scale({}, {});  // {}", p2, p, inv, describe(n)));
        Value c = emit(n.children[0], p2);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};  // undo the scale on the distance", d, c.d, r(0)));
        return with_d(c, d);
      }
      case Kind::StepFactor: {
        Value c = emit(n.children[0], p);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};  // {}", d, c.d, r(0), describe(n)));
        return with_d(c, d);
      }
      case Kind::Bounded: {
        if (blend_) return emit(n.children[0], p);  // once per hit: no box test
        // Skip the subtree while every lane is farther from its box than the
        // margin: the box distance is a lower bound of the subtree's.
        ir::Vec3d c, h;
        for (int i = 0; i < 3; ++i) c[i] = 0.5 * (q[i] + q[i + 3]), h[i] = 0.5 * (q[i + 3] - q[i]);
        std::string b = var("b"), d = var("d"), m = with_mat_ ? var("m") : "";
        w_.line(fmt::format("real {} = {}(v3_sub({}, {}), {}, {});  // bounding box{}", b, call("sd_box"), p, lit_.vec3(c),
                            lit_.vec3(h), lit_.real(0), where(n)));
        w_.line(fmt::format("real {} = {};", d, b));
        if (with_mat_) w_.line(fmt::format("real {} = {};", m, lit_.typed(0)));
        w_.line(fmt::format("if (M_ANY({} <= {}))", b, r(6)));
        w_.open("{");
        Value inner = emit(n.children[0], p);
        w_.line(fmt::format("{} = SEL({}, {}, {} > {});", d, inner.d, b, b, r(6)));
        if (with_mat_) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, inner.mat, lit_.typed(0), b, r(6)));
        w_.close("}");
        return {d, m};
      }
      case Kind::Material: {
        if (blend_) {  // top-down: the material nearest the geometry is set last
          double outer = cur_mat_;
          cur_mat_ = q[0];
          Value c = emit(n.children[0], p);
          cur_mat_ = outer;
          return c;
        }
        Value c = emit(n.children[0], p);
        if (!with_mat_ || trap_) return c;
        std::string id = lit_.typed(q[0]);
        // The material nearest the geometry wins: only unassigned (0) parts take this one.
        if (c.mat == lit_.typed(0)) return {c.d, id};
        std::string m = var("m");
        w_.line(fmt::format("real {} = SEL({}, {}, {} != 0.0f);  // {}", m, id, c.mat, c.mat, describe(n)));
        return {c.d, m};
      }
      case Kind::ObjectSet: {  // a large union held as data (object_set_emitter.cpp)
        ObjectSetCode c = emit_object_set(n, p, where(n), w_, used_);
        if (trap_) return {c.d, lit_.typed(0)};  // no fractal inside: no trap
        if (!blend_) return {c.d, with_mat_ ? c.mat : ""};
        std::string id = var("m");  // items without a material of their own show the one above the set
        w_.line(fmt::format("real {} = SEL({}, {}, {} != 0.0f);", id, lit_.typed(cur_mat_), c.mat, c.mat));
        return {c.d, id, object_set_record(id, module_, lit_, w_, used_)};
      }
      // ---- issue 9: domain operations ----
      case Kind::Repeat: return repeat(n, p);
      case Kind::PolarRepeat: {
        std::string near = var("p"), own = var("p");
        w_.line(fmt::format("vec3 {};  // {}", near, describe(n)));
        w_.line(fmt::format("vec3 {} = {}({}, {}, {}, &{});", own, call("dm_polar"), p, int(q[0]), r(1), near));
        return cells(n, {own, near});
      }
      case Kind::Mirror: {
        std::string p2 = var("p");
        auto axis = [&](int i, const char* c) { return q[i] != 0 ? fmt::format("fabs({}.{})", p, c) : p + "." + c; };
        w_.line(fmt::format("vec3 {} = v3({}, {}, {});  // {}", p2, axis(0, "x"), axis(1, "y"), axis(2, "z"), describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::Symmetry: {
        std::string p2 = var("p");
        std::string fn = q[0] != 0 ? "dm_symmetry_octahedral" : "dm_symmetry_tetrahedral";
        w_.line(fmt::format("vec3 {} = {}({});  // {}", p2, call(fn), p, describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::Twist:
      case Kind::Bend: {
        std::string p2 = var("p");
        std::string fn = n.kind == Kind::Twist ? "dm_twist" : "dm_bend";
        w_.line(fmt::format("vec3 {} = {}({}, {}, {});  // {}", p2, call(fn), p, int(q[0]), r(1), describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::Elongate: {
        std::string p2 = var("p");
        auto axis = [&](int i, const char* c) {
          return fmt::format("{0}.{1} - clamp({0}.{1}, K({2}), K({3}))", p, c, lit_.real(-q[i]), r(i));
        };
        w_.line(fmt::format("vec3 {} = v3({}, {}, {});  // {}", p2, axis(0, "x"), axis(1, "y"), axis(2, "z"), describe(n)));
        return emit(n.children[0], p2);
      }
      case Kind::ScaleXYZ: {
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_mul({}, {});  // {}", p2, p, lit_.vec3({1 / q[0], 1 / q[1], 1 / q[2]}), describe(n)));
        Value c = emit(n.children[0], p2);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};  // the smallest factor keeps it a bound", d, c.d,
                            lit_.real(std::min({q[0], q[1], q[2]}))));
        return with_d(c, d);
      }
      case Kind::Round:
      case Kind::Onion:
      case Kind::Shell: {
        Value c = emit(n.children[0], p);
        std::string d = var("d");
        std::string e = n.kind == Kind::Round   ? fmt::format("{} - {}", c.d, r(0))
                         : n.kind == Kind::Onion ? fmt::format("fabs({}) - {}", c.d, r(0))
                                                 : fmt::format("fmax({0}, -{0} - {1})", c.d, r(0));
        w_.line(fmt::format("real {} = {};  // {}", d, e, describe(n)));
        return with_d(c, d);
      }
      case Kind::Displace: {
        Value c = emit(n.children[0], p);
        const expr::ExprPtr& e = g_.expressions.at(size_t(q[0]));
        std::string body = expr::to_opencl(
            e, [&](std::string_view var) { return var == "time" ? std::string("time") : p + "." + std::string(var); },
            [&](double x) { return lit_.typed(x); });
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} + {};  // displace {}{}", d, c.d, body, kernel_text(expr::to_string(e)), where(n)));
        return with_d(c, d);
      }
      default:
        if (auto e = kind_call(n, p, lit_, used_)) return leaf(n, *e);
        if (is_fractal(n)) {
          std::string expr = emit_fractal(n, p, lit_, w_, used_);
          Value v = leaf(n, expr);
          const OrbitValue value = iterations_           ? OrbitValue::Escape
                                   : iteration_.count(id) ? OrbitValue::Smooth
                                                          : OrbitValue::Trap;
          std::optional<size_t> shape;
          if (auto it = shaped_.find(id); it != shaped_.end() && value == OrbitValue::Trap) shape = it->second;
          std::string trap = trap_ ? emit_fractal_trap(n, p, lit_, w_, used_, value, shape) : "";
          if (!trap.empty()) {
            v.mat = var(iterations_ ? "it" : "trap");
            w_.line(fmt::format("real {} = {};  // {}", v.mat, trap,
                                iterations_            ? "iteration count"
                                : iteration_.count(id) ? "smooth iteration count (its material's source)"
                                                       : "orbit trap"));
          }
          return v;
        }
        return combine(n, p);
    }
  }

  Value combine(const ir::Node& n, const std::string& p) {
    std::vector<Value> kids;
    for (NodeId c : n.children) kids.push_back(emit(c, p));
    std::string d = var("d"), m = with_mat_ ? var("m") : "";
    w_.line(fmt::format("real {} = {};  // {}", d, kids[0].d, describe(n)));
    bool track = with_mat_;
    bool any_mat = false;
    for (const auto& k : kids) any_mat = any_mat || k.mat != lit_.typed(0);
    if (track && !any_mat) track = false, m = lit_.typed(0);
    if (track) w_.line(fmt::format("real {} = {};", m, kids[0].mat));
    std::string rec = blend_ ? var("r") : "";
    if (blend_) w_.line(fmt::format("mat_record {} = {};", rec, kids[0].rec));
    for (size_t i = 1; i < kids.size(); ++i) {
      const Value& k = kids[i];
      if (blend_) blend_record(n, rec, d, k);
      switch (n.kind) {
        case Kind::Union:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = fmin({}, {});", d, d, k.d));
          break;
        case Kind::SmoothUnion:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_union"), d, k.d, param(n, 0, lit_)));
          break;
        case Kind::Intersection:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = fmax({}, {});", d, d, k.d));
          break;
        case Kind::SmoothIntersection:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_intersection"), d, k.d, param(n, 0, lit_)));
          break;
        case Kind::Difference:  // the cut face keeps the first child's material
          w_.line(fmt::format("{} = fmax({}, -{});", d, d, k.d));
          break;
        case Kind::SmoothDifference:
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_difference"), d, k.d, param(n, 0, lit_)));
          break;
        // Blends (issue 9): intersection and difference are the union's dual.
        case Kind::BlendUnion:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = {};", d, blend(n, d, k.d)));
          break;
        case Kind::BlendIntersection:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = -{};", d, blend(n, "-" + d, "-" + k.d)));
          break;
        case Kind::BlendDifference:
          w_.line(fmt::format("{} = -{};", d, blend(n, "-" + d, k.d)));
          break;
        default: break;
      }
    }
    return {d, with_mat_ ? m : "", rec};
  }

  // scene_material: folds child k's record into rec (the children before it,
  // whose combined distance is d), before d takes k in. Smooth blends mix by
  // the share of k in the blended distance (its derivative in k's distance);
  // the intersection is -U(-a, -b) and the difference -U(-a, b), so their
  // weights are the union's at the negated distances. Hard operations and
  // the stylised blends take the nearer child; a difference keeps the first.
  void blend_record(const ir::Node& n, const std::string& rec, const std::string& d, const Value& k) {
    bool uni = n.kind == Kind::Union || n.kind == Kind::SmoothUnion || n.kind == Kind::BlendUnion;
    bool inter = n.kind == Kind::Intersection || n.kind == Kind::SmoothIntersection || n.kind == Kind::BlendIntersection;
    if (!ir::mixes_materials(n)) {
      if (uni || inter)
        w_.line(fmt::format("{} = mat_select({}, {}, {} {} {});", rec, rec, k.rec, k.d, uni ? "<" : ">", d));
      return;
    }
    bool poly = n.kind == Kind::SmoothUnion || n.kind == Kind::SmoothIntersection || n.kind == Kind::SmoothDifference;
    std::string fn = poly ? "op_weight_polynomial" : n.params[0] == 0 ? "op_weight_cubic" : "op_weight_exponential";
    std::string radius = "(real)(" + param(n, poly ? 0 : 1, lit_) + ")";  // may be animated
    std::string a = uni ? d : "-" + d, b = inter ? "-" + k.d : k.d;
    w_.line(fmt::format("{} = mat_mix({}, {}, {}({}, {}, {}));  // blend weight", rec, rec, k.rec, call(fn), a, b, radius));
  }

  // The union-style blend of a and b for a Blend* node.
  std::string blend(const ir::Node& n, const std::string& a, const std::string& b) {
    static const char* fns[] = {"op_blend_cubic", "op_blend_exponential", "op_blend_chamfer",
                                "op_blend_round", "op_blend_columns",     "op_blend_stairs"};
    int style = int(n.params[0]);
    std::string steps = style >= 4 ? ", " + lit_.typed(n.params[2]) : "";
    return fmt::format("{}({}, {}, (real)({}){})", call(fns[style]), a, b, param(n, 1, lit_), steps);  // radius may be animated
  }

  // repeat: the child in the point's own cell and in the neighbouring cell on
  // each repeated axis (2^k evaluations), so a child that reaches across the
  // cell border leaves no seam; every other copy is at least
  // period - reach + |u| away along some axis, which bounds the rest.
  Value repeat(const ir::Node& n, const std::string& p) {
    const auto& q = n.params;
    const ir::Box3& cb = g_.node(n.children[0]).props.bounds;
    const char* xyz[] = {"x", "y", "z"};
    std::string own[3], near[3], rest;
    std::vector<int> axes;
    w_.line("// " + describe(n));
    for (int i = 0; i < 3; ++i) {
      own[i] = p + "." + xyz[i];
      near[i] = own[i];
      if (q[3 + i] == 1) continue;
      axes.push_back(i);
      own[i] = var("u"), near[i] = var("nb");
      w_.line(fmt::format("real {};", near[i]));
      w_.line(fmt::format("real {} = {}({}.{}, {}, {}, &{});", own[i], call("dm_repeat_axis"), p, xyz[i],
                          lit_.typed(q[i]), lit_.typed(q[3 + i]), near[i]));
      double reach = std::max(std::fabs(cb.lo[i]), std::fabs(cb.hi[i]));
      std::string term = fmt::format("{} + fabs({})", lit_.real(q[i] - reach), own[i]);
      rest = rest.empty() ? term : fmt::format("fmin({}, {})", rest, term);
    }
    std::vector<std::string> points;
    for (int c = 0; c < (1 << axes.size()); ++c) {
      std::string comp[3] = {own[0], own[1], own[2]};
      for (size_t a = 0; a < axes.size(); ++a)
        if (c & (1 << a)) comp[axes[a]] = near[axes[a]];
      points.push_back(fmt::format("v3({}, {}, {})", comp[0], comp[1], comp[2]));
    }
    Value v = cells(n, points);
    std::string d = var("d");
    w_.line(fmt::format("real {} = fmin({}, {});  // copies beyond the neighbours are farther", d, v.d, rest));
    return with_d(v, d);
  }

  // The minimum of the child over several points (one loop, the child's code once).
  Value cells(const ir::Node& n, const std::vector<std::string>& points) {
    std::string d = var("d"), m = with_mat_ ? var("m") : "", c = var("c"), rec = blend_ ? var("r") : "";
    w_.line(fmt::format("real {} = {};", d, lit_.typed(1e30)));
    if (with_mat_) w_.line(fmt::format("real {} = {};", m, lit_.typed(0)));
    if (blend_) w_.line(fmt::format("mat_record {} = mat_none();", rec));
    w_.open(fmt::format("for (int {0} = 0; {0} < {1}; ++{0}) {{", c, points.size()));
    std::string pc = var("p");
    std::string pick = points.back();
    for (size_t i = points.size() - 1; i-- > 0;) pick = fmt::format("{} == {} ? {} : {}", c, i, points[i], pick);
    w_.line(fmt::format("vec3 {} = {};", pc, pick));
    Value k = emit(n.children[0], pc);
    if (with_mat_) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
    if (blend_) w_.line(fmt::format("{} = mat_select({}, {}, {} < {});", rec, rec, k.rec, k.d, d));
    w_.line(fmt::format("{} = fmin({}, {});", d, d, k.d));
    w_.close("}");
    return {d, m, rec};
  }

  // The fractals whose material (the nearest material above them, as for
  // scene_dist_mat) colours by the smooth iteration count instead of the
  // trap, and those whose material's trap has a shape.
  void find_iteration_fractals(const ir::Module& m, NodeId id, int material) {
    const ir::Node& n = g_.node(id);
    if (n.kind == Kind::Material) material = int(n.params[0]);
    if (is_fractal(n) && material > 0 && size_t(material) < m.plan.materials.size() &&
        m.plan.materials[size_t(material)].trap_source == ir::MaterialDef::TrapSource::Iteration)
      iteration_.insert(id);
    if (is_fractal(n) && material > 0 && shaped_trap(m.plan, size_t(material))) shaped_[id] = size_t(material);
    for (NodeId c : n.children) find_iteration_fractals(m, c, material);
  }

  const ir::Graph& g_;
  const ir::Module& module_;
  const ir::RenderPlan& plan_;
  const Literals& lit_;
  bool with_mat_;
  bool trap_;
  bool blend_;
  double cur_mat_ = 0;  // scene_material: the material of the nearest material node above
  std::string leaf_p_;
  std::set<NodeId> iteration_;
  std::map<NodeId, size_t> shaped_;  // fractals whose material's trap has a shape, and that material
  bool iterations_;
  std::set<std::string>& used_;
  bool orbit_traps_;
  bool coloring_geometry_;
  std::string file_;
  CodeWriter w_;
};

}  // namespace

std::string emit_scene_material(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  std::string out = "// ---- scene material: evaluated once per hit; smooth blends mix their children's materials ----\n";
  return out + SceneEmitter(m, lit, false, used, false, true).function(m.root);
}

std::string emit_scene_iterations(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  return "// ---- iteration count of the nearest fractal (0 elsewhere): the iterations AOV, once per pixel ----\n" +
         SceneEmitter(m, lit, false, used, false, false, true).function(m.root);
}

std::string emit_scene_functions(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  used.insert("vec3_ops");
  std::string out = "// ---- scene distance: the march evaluates this at every step ----\n";
  out += SceneEmitter(m, lit, false, used).function(m.root);
  out += "\n// ---- scene distance with material: evaluated once per hit ----\n";
  out += SceneEmitter(m, lit, true, used).function(m.root);
  if (m.analyses.orbit_traps && !m.analyses.material_blend) {  // with blends, scene_material applies the traps
    out += "\n// ---- orbit trap of the nearest fractal: evaluated once per hit, for orbit-trap materials ----\n";
    out += SceneEmitter(m, lit, false, used, true).function(m.root);
  }
  return out;
}

}  // namespace sdfc::codegen::detail
