// fold_constants: merge nested transforms, drop identity transforms and
// inner materials that an inner material overrides, collapse combinators
// with one child.
#include "rewrite.hpp"
#include "sdfc/kinds/folding.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace detail {

ir::NodeId fold_node(ir::Builder& b, ir::Kind k, std::vector<double> params, std::vector<ir::NodeId> kids,
                     const SourceLoc& loc, ir::Animation anim) {
  const ir::Graph& g = b.graph();
  auto child = [&](size_t i) -> const ir::Node& { return g.node(kids[i]); };
  // Animated transforms change with time: they neither vanish nor merge.
  bool animated = false;
  for (const auto& e : anim) animated = animated || e;
  bool merge = !animated && !kids.empty() && !child(0).animated();
  if (animated && ir::info(k).category == ir::Category::Transform)
    return b.make(k, std::move(params), std::move(kids), loc, std::move(anim));
  if (const kinds::Description* d = kinds::operation(k); d && d->fold) {
    kinds::Folding f{g, params, kids, merge, [&](std::vector<double> p, std::vector<ir::NodeId> c) {
                       return fold_node(b, k, std::move(p), std::move(c), loc);
                     }};
    if (ir::NodeId r = d->fold(f); r != ir::kNoNode) return r;
  }
  if (ir::info(k).arity == -1 && kids.size() == 1) return kids[0];
  return b.make(k, std::move(params), std::move(kids), loc, std::move(anim));
}

}  // namespace detail

ir::Module fold_constants(ir::Module m) {
  return detail::rewrite(std::move(m), [](ir::Builder& b, const ir::Node& n, std::vector<ir::NodeId> kids) {
    return detail::fold_node(b, n.kind, n.params, std::move(kids), n.loc, n.anim);
  });
}

}  // namespace sdfc::passes
