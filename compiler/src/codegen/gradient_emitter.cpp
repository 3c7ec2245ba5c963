// render.normals: dual. The distance and its gradient flow up together; the
// combinators pick the gradient of the child whose distance they pick, the
// transforms map it back to world space.
#include "gradient_emitter.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "fractal_emitter.hpp"
#include "kind_call.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::Kind;
using ir::NodeId;

struct DG {
  std::string d, g;
};

class GradientEmitter {
 public:
  GradientEmitter(const ir::Module& m, const Literals& lit, std::set<std::string>& used)
      : g_(*m.graph), lit_(lit), used_(used) {}

  std::string function(NodeId root) {
    w_.line("vec3 scene_normal_dual(vec3 p)");
    w_.open("{");
    DG v = emit(root, "p");
    w_.line(fmt::format("(void){};", v.d));
    w_.line(fmt::format("return v3_normalize({});", v.g));
    w_.close("}");
    return w_.take();
  }

 private:
  std::string var(const char* prefix) { return fmt::format("{}{}", prefix, w_.fresh()); }

  DG leaf(const std::string& fn, const std::string& args, const ir::Node& n) {
    used_.insert(fn);
    DG v{var("d"), var("g")};
    w_.line(fmt::format("vec3 {};", v.g));
    w_.line(fmt::format("real {} = {}({}, &{});  // {}", v.d, fn, args, v.g, ir::info(n.kind).name));
    return v;
  }

  DG emit(NodeId id, const std::string& p) {
    const ir::Node& n = g_.node(id);
    const auto& q = n.params;
    auto r = [&](size_t i) { return lit_.real(q[i]); };
    switch (n.kind) {
      // Described kinds: the description's gradient function, same arguments.
      default: break;
      case Kind::Translate: {
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_sub({}, {});", p2, p, lit_.vec3({q[0], q[1], q[2]})));
        return emit(n.children[0], p2);
      }
      case Kind::Rotate: {
        // The point goes world->local (the transpose), the gradient local->world.
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {});", p2, p, r(0), r(3), r(6), r(1),
                            r(4), r(7), r(2), r(5), r(8)));
        DG c = emit(n.children[0], p2);
        std::string g = var("g");
        w_.line(fmt::format("vec3 {} = v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {});", g, c.g, r(0), r(1), r(2), r(3),
                            r(4), r(5), r(6), r(7), r(8)));
        return {c.d, g};
      }
      case Kind::Scale: {
        // d(p) = s d_c(p / s): the gradient is the child's.
        std::string p2 = var("p");
        w_.line(fmt::format("vec3 {} = v3_scale({}, {});", p2, p, lit_.real(1.0 / q[0])));
        DG c = emit(n.children[0], p2);
        std::string d = var("d");
        w_.line(fmt::format("real {} = {} * {};", d, c.d, r(0)));
        return {d, c.g};
      }
      case Kind::StepFactor: {
        DG c = emit(n.children[0], p);
        std::string d = var("d"), g = var("g");
        w_.line(fmt::format("real {} = {} * {};", d, c.d, r(0)));
        w_.line(fmt::format("vec3 {} = v3_scale({}, {});", g, c.g, r(0)));
        return {d, g};
      }
      case Kind::Material: return emit(n.children[0], p);
      // A bounding box the optimiser inserted: at a hit the point is inside
      // its margin, so the distance and gradient are the child's.
      case Kind::Bounded: return emit(n.children[0], p);
      case Kind::SmoothUnion:
      case Kind::SmoothIntersection:
      case Kind::SmoothDifference: {
        std::vector<DG> kids;
        for (NodeId c : n.children) kids.push_back(emit(c, p));
        used_.insert("opg_smooth");
        DG v{var("d"), var("g")};
        std::string k = r(0);
        w_.line(fmt::format("real {} = {};  // {}", v.d, kids[0].d, ir::info(n.kind).name));
        w_.line(fmt::format("vec3 {} = {};", v.g, kids[0].g));
        for (size_t i = 1; i < kids.size(); ++i) {
          const DG& c = kids[i];
          if (n.kind == Kind::SmoothUnion) {
            used_.insert("op_smooth_union");
            w_.line(fmt::format("{} = opg_smooth({}, {}, {}, {}, {}, 1.0f);", v.g, v.d, c.d, v.g, c.g, k));
            w_.line(fmt::format("{} = op_smooth_union({}, {}, {});", v.d, v.d, c.d, k));
          } else if (n.kind == Kind::SmoothIntersection) {
            used_.insert("op_smooth_intersection");
            w_.line(fmt::format("{} = opg_smooth({}, {}, {}, {}, {}, -1.0f);", v.g, v.d, c.d, v.g, c.g, k));
            w_.line(fmt::format("{} = op_smooth_intersection({}, {}, {});", v.d, v.d, c.d, k));
          } else {
            used_.insert("op_smooth_intersection");
            w_.line(fmt::format("{} = opg_smooth({}, -{}, {}, v3_scale({}, -1.0f), {}, -1.0f);", v.g, v.d, c.d, v.g, c.g, k));
            w_.line(fmt::format("{} = op_smooth_intersection({}, -{}, {});", v.d, v.d, c.d, k));
          }
        }
        return v;
      }
      case Kind::Union:
      case Kind::Intersection:
      case Kind::Difference: {
        std::vector<DG> kids;
        for (NodeId c : n.children) kids.push_back(emit(c, p));
        DG v{var("d"), var("g")};
        w_.line(fmt::format("real {} = {};  // {}", v.d, kids[0].d, ir::info(n.kind).name));
        w_.line(fmt::format("vec3 {} = {};", v.g, kids[0].g));
        for (size_t i = 1; i < kids.size(); ++i) {
          const DG& k = kids[i];
          if (n.kind == Kind::Union) {
            w_.line(fmt::format("{} = v3_select({}, {}, {} < {});", v.g, v.g, k.g, k.d, v.d));
            w_.line(fmt::format("{} = fmin({}, {});", v.d, v.d, k.d));
          } else if (n.kind == Kind::Intersection) {
            w_.line(fmt::format("{} = v3_select({}, {}, {} > {});", v.g, v.g, k.g, k.d, v.d));
            w_.line(fmt::format("{} = fmax({}, {});", v.d, v.d, k.d));
          } else {
            w_.line(fmt::format("{} = v3_select({}, v3_scale({}, -1.0f), -{} > {});", v.g, v.g, k.g, k.d, v.d));
            w_.line(fmt::format("{} = fmax({}, -{});", v.d, v.d, k.d));
          }
        }
        return v;
      }
    }
    const kinds::Description* d = kinds::find(n.kind);
    if (d && d->emit_dual) return fractal(n, p);
    if (!d || d->gradient_function.empty())
      throw std::logic_error(fmt::format("dual normals reached '{}', which the front end should have refused",
                                           ir::info(n.kind).name));
    return leaf(std::string(d->gradient_function), p + ", " + kind_args(n, lit_, false), n);
  }

  // A fractal: its distance exactly as scene_dist computes it (so the
  // combinators choose the same child), and as gradient the unit direction
  // of grad |z_n| from dual numbers through the orbit (a good estimator has
  // |grad d| ~ 1, so this is its gradient where it matters, at the surface).
  DG fractal(const ir::Node& n, const std::string& p) {
    DG v{var("d"), var("g")};
    w_.line(fmt::format("real {} = {};  // {}", v.d, emit_fractal(n, p, lit_, w_, used_), ir::info(n.kind).name));
    w_.line(fmt::format("vec3 {} = {};  // the direction of grad |z_n|", v.g, emit_fractal_dual(n, p, lit_, w_, used_)));
    return v;
  }

  const ir::Graph& g_;
  const Literals& lit_;
  std::set<std::string>& used_;
  CodeWriter w_;
};

}  // namespace

std::string emit_scene_gradient(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  used.insert("vec3_ops");
  return "// ---- the scene's exact gradient (render.normals: dual), evaluated once per hit ----\n" +
         GradientEmitter(m, lit, used).function(m.root);
}

}  // namespace sdfc::codegen::detail
