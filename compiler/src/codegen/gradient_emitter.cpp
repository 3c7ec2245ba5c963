// render.normals: dual. The distance and its gradient flow up together; the
// combinators pick the gradient of the child whose distance they pick, the
// transforms map it back to world space (their descriptions' walk_dual).
#include "gradient_emitter.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "fractal_emitter.hpp"
#include "kind_call.hpp"
#include "../kinds/walker.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::codegen::detail {

namespace {

using ir::NodeId;

using DG = kinds::Dual;

class GradientEmitter final : public kinds::DualWalker {
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

  DG leaf(const std::string& fn, const std::string& args, const ir::Node& n) {
    used_.insert(fn);
    DG v{var("d"), var("g")};
    w_.line(fmt::format("vec3 {};", v.g));
    w_.line(fmt::format("real {} = {}({}, &{});  // {}", v.d, fn, args, v.g, ir::info(n.kind).name));
    return v;
  }

  // kinds::DualWalker, for the kinds with children.
  DG child(NodeId id, const std::string& p) override { return emit(id, p); }
  void line(const std::string& s) override { w_.line(s); }
  std::string var(const char* prefix) override { return fmt::format("{}{}", prefix, w_.fresh()); }
  std::string call(const std::string& fn) override {
    used_.insert(fn);
    return fn;
  }
  const Literals& lit() const override { return lit_; }

 private:
  DG emit(NodeId id, const std::string& p) {
    const ir::Node& n = g_.node(id);
    if (const kinds::Description* d = kinds::operation(n.kind); d && d->walk_dual) return d->walk_dual(*this, n, p);
    const kinds::Description* d = kinds::find(n.kind);
    if (d && d->emit_dual) return fractal(n, p);
    if (!d || d->gradient_function.empty())
      throw std::logic_error(fmt::format("dual normals reached '{}', which the front end should have refused",
                                           ir::info(n.kind).name));
    return leaf(std::string(d->gradient_function), p + ", " + kind_args(n, lit_, false), n);
  }

  // A fractal: its distance exactly as scene_dist computes it (so the
  // combinators choose the same child), and the normal's direction from
  // dual numbers through the orbit: a built-in kind's direction of
  // grad |z_n|, a formula's exact gradient of its estimate (a good estimator
  // has |grad d| ~ 1, so either serves where it matters, at the surface).
  DG fractal(const ir::Node& n, const std::string& p) {
    DG v{var("d"), var("g")};
    w_.line(fmt::format("real {} = {};  // {}", v.d, emit_fractal(n, p, lit_, w_, used_), ir::info(n.kind).name));
    w_.line(fmt::format("vec3 {} = {};  // the normal's direction", v.g, emit_fractal_dual(n, p, lit_, w_, used_)));
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
