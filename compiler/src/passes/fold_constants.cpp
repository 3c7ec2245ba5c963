// fold_constants: merge nested transforms, drop identity transforms and
// inner materials that an inner material overrides, collapse combinators
// with one child.
#include <cmath>

#include "rewrite.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace detail {

namespace {

bool is_identity(const std::vector<double>& m) {
  static const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < 9; ++i)
    if (std::fabs(m[i] - I[i]) > 1e-12) return false;
  return true;
}

std::vector<double> mat_mul(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> r(9, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i * 3 + j] += a[i * 3 + k] * b[k * 3 + j];
  return r;
}

}  // namespace

ir::NodeId fold_node(ir::Builder& b, ir::Kind k, std::vector<double> params, std::vector<ir::NodeId> kids,
                     const SourceLoc& loc, ir::Animation anim) {
  using ir::Kind;
  const ir::Graph& g = b.graph();
  auto child = [&](size_t i) -> const ir::Node& { return g.node(kids[i]); };
  // Animated transforms change with time: they neither vanish nor merge.
  bool animated = false;
  for (const auto& e : anim) animated = animated || e;
  bool merge = !animated && !kids.empty() && !child(0).animated();
  if (animated && ir::info(k).category == ir::Category::Transform)
    return b.make(k, std::move(params), std::move(kids), loc, std::move(anim));
  switch (k) {
    case Kind::Translate:
      if (params[0] == 0 && params[1] == 0 && params[2] == 0) return kids[0];
      if (merge && child(0).kind == Kind::Translate) {
        const ir::Node& c = child(0);
        return fold_node(b, k, {params[0] + c.params[0], params[1] + c.params[1], params[2] + c.params[2]},
                         c.children, loc);
      }
      break;
    case Kind::Rotate:
      if (is_identity(params)) return kids[0];
      if (merge && child(0).kind == Kind::Rotate) {
        const ir::Node& c = child(0);
        return fold_node(b, k, mat_mul(params, c.params), c.children, loc);
      }
      break;
    case Kind::Scale:
      if (params[0] == 1) return kids[0];
      if (merge && child(0).kind == Kind::Scale) {
        const ir::Node& c = child(0);
        return fold_node(b, k, {params[0] * c.params[0]}, c.children, loc);
      }
      break;
    case Kind::Material:
      // The material nearest the geometry wins, so an outer one is dead.
      if (child(0).kind == Kind::Material) return kids[0];
      break;
    default:
      if (ir::info(k).arity == -1 && kids.size() == 1) return kids[0];
      break;
  }
  return b.make(k, std::move(params), std::move(kids), loc, std::move(anim));
}

}  // namespace detail

ir::Module fold_constants(ir::Module m) {
  return detail::rewrite(std::move(m), [](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    return detail::fold_node(b, n.kind, n.params, std::move(kids), n.loc, n.anim);
  });
}

}  // namespace sdfc::passes
