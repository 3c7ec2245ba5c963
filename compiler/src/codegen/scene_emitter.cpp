// Geometry to OpenCL C: one statement per IR node, each commented with the
// node and the YAML line it came from. Points flow down (transforms make new
// point variables), distances flow up.
#include "scene_emitter.hpp"

#include <fmt/format.h>

#include "fractal_emitter.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;
using ir::NodeId;

struct Value {
  std::string d;    // distance variable
  std::string mat;  // material variable or real-typed literal; "" when not tracked
};

class SceneEmitter {
 public:
  // trap: emit scene_trap instead, where the tracked value is the orbit
  // trap of the nearest fractal (chosen by the same rules as the material).
  SceneEmitter(const ir::Module& m, const Literals& lit, bool with_mat, std::set<std::string>& used, bool trap = false)
      : g_(*m.graph), lit_(lit), with_mat_(with_mat || trap), trap_(trap), used_(used), file_(m.source_name) {}

  std::string function(NodeId root) {
    w_.line(trap_ ? "real scene_trap(vec3 p)" : with_mat_ ? "real scene_dist_mat(vec3 p, real* mat)" : "real scene_dist(vec3 p)");
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
    return fmt::format("  ({}:{})", f, n.loc.line);
  }

  std::string describe(const ir::Node& n) const {
    const ir::KindInfo& k = ir::info(n.kind);
    std::string s(k.name);
    for (size_t i = 0; i < n.params.size() && n.kind != Kind::Rotate; ++i)
      s += fmt::format(" {}={}", k.params[i], n.params[i]);
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
    return {d, with_mat_ ? lit_.typed(0) : ""};
  }

  Value emit(NodeId id, const std::string& p) {
    const ir::Node& n = g_.node(id);
    const auto& q = n.params;
    auto r = [&](size_t i) { return lit_.real(q[i]); };
    switch (n.kind) {
      case Kind::Sphere: return leaf(n, fmt::format("{}({}, {})", call("sd_sphere"), p, r(0)));
      case Kind::Box:
        return leaf(n, fmt::format("{}({}, {}, {})", call("sd_box"), p, lit_.vec3({q[0], q[1], q[2]}), r(3)));
      case Kind::Torus: return leaf(n, fmt::format("{}({}, {}, {})", call("sd_torus"), p, r(0), r(1)));
      case Kind::Plane:
        return leaf(n, fmt::format("{}({}, {}, {})", call("sd_plane"), p, lit_.vec3({q[0], q[1], q[2]}), r(3)));
      case Kind::Cylinder: return leaf(n, fmt::format("{}({}, {}, {})", call("sd_cylinder"), p, r(0), r(1)));
      case Kind::Capsule:
        return leaf(n, fmt::format("{}({}, {}, {}, {})", call("sd_capsule"), p, lit_.vec3({q[0], q[1], q[2]}),
                                   lit_.vec3({q[3], q[4], q[5]}), r(6)));
      case Kind::Translate: {
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_sub({}, {});  // {}", p2, p, lit_.vec3({q[0], q[1], q[2]}), describe(n)));
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
        w_.line(fmt::format("vec3 {} = v3_scale({}, {});  // {}", p2, p, lit_.real(1.0 / q[0]), describe(n)));
        Value c = emit(n.children[0], p2);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};  // undo the scale on the distance", d, c.d, r(0)));
        return {d, c.mat};
      }
      case Kind::StepFactor: {
        Value c = emit(n.children[0], p);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};  // {}", d, c.d, r(0), describe(n)));
        return {d, c.mat};
      }
      case Kind::Material: {
        Value c = emit(n.children[0], p);
        if (!with_mat_ || trap_) return c;
        std::string id = lit_.typed(q[0]);
        // The material nearest the geometry wins: only unassigned (0) parts take this one.
        if (c.mat == lit_.typed(0)) return {c.d, id};
        std::string m = var("m");
        w_.line(fmt::format("real {} = SEL({}, {}, {} != 0.0f);  // {}", m, id, c.mat, c.mat, describe(n)));
        return {c.d, m};
      }
      default:
        if (is_fractal(n)) {
          std::string expr = emit_fractal(n, p, lit_, w_, used_);
          Value v = leaf(n, expr);
          std::string trap = trap_ ? emit_fractal_trap(n, p, lit_, used_) : "";
          if (!trap.empty()) {
            v.mat = var("trap");
            w_.line(fmt::format("real {} = {};  // orbit trap", v.mat, trap));
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
    for (size_t i = 1; i < kids.size(); ++i) {
      const Value& k = kids[i];
      switch (n.kind) {
        case Kind::Union:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = fmin({}, {});", d, d, k.d));
          break;
        case Kind::SmoothUnion:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} < {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_union"), d, k.d, lit_.real(n.params[0])));
          break;
        case Kind::Intersection:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = fmax({}, {});", d, d, k.d));
          break;
        case Kind::SmoothIntersection:
          if (track) w_.line(fmt::format("{} = SEL({}, {}, {} > {});", m, m, k.mat, k.d, d));
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_intersection"), d, k.d, lit_.real(n.params[0])));
          break;
        case Kind::Difference:  // the cut face keeps the first child's material
          w_.line(fmt::format("{} = fmax({}, -{});", d, d, k.d));
          break;
        case Kind::SmoothDifference:
          w_.line(fmt::format("{} = {}({}, {}, {});", d, call("op_smooth_difference"), d, k.d, lit_.real(n.params[0])));
          break;
        default: break;
      }
    }
    return {d, with_mat_ ? m : ""};
  }

  const ir::Graph& g_;
  const Literals& lit_;
  bool with_mat_;
  bool trap_;
  std::set<std::string>& used_;
  std::string file_;
  CodeWriter w_;
};

}  // namespace

std::string emit_scene_functions(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  used.insert("vec3_ops");
  std::string out = "// ---- scene distance: the march evaluates this at every step ----\n";
  out += SceneEmitter(m, lit, false, used).function(m.root);
  out += "\n// ---- scene distance with material: evaluated once per hit ----\n";
  out += SceneEmitter(m, lit, true, used).function(m.root);
  bool traps = false;
  for (const auto& md : m.plan.materials) traps = traps || !md.trap_palette.empty();
  if (traps) {
    out += "\n// ---- orbit trap of the nearest fractal: evaluated once per hit, for orbit-trap materials ----\n";
    out += SceneEmitter(m, lit, false, used, true).function(m.root);
  }
  return out;
}

}  // namespace sdfc::codegen::detail
