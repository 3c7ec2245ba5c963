// union, intersection and difference: the hard folds, min and max of the
// children's distances.
#include "combinator.hpp"

SDFC_KIND(Union,              10, "union",               Combinator, -1, "",                             "")
SDFC_KIND(Intersection,       11, "intersection",        Combinator, -1, "",                             "")
SDFC_KIND(Difference,         12, "difference",          Combinator, -1, "",                             "")

namespace sdfc::kinds {
namespace {
using namespace combinator;

template <Select S>
ir::Props props(const ir::Graph&, const ir::Node& n, const Kid& kid) { return fold_props(n, kid, S, 2); }

template <Select S>
Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  return fold_samples(g, n, p, [](Sample& acc, const Sample& b) {
    double d = S == Select::Nearer  ? std::min(acc.distance, b.distance)
               : S == Select::Farther ? std::max(acc.distance, b.distance)
                                      : std::max(acc.distance, -b.distance);
    select_sample(acc, b, S, d);
  });
}

Carried union_walk(Walker& w, const ir::Node& n, const std::string& p) {
  return combine(w, n, p, {Select::Nearer, [](auto& d, auto& b) { return fmt::format("fmin({}, {})", d, b); }});
}
Carried intersection_walk(Walker& w, const ir::Node& n, const std::string& p) {
  return combine(w, n, p, {Select::Farther, [](auto& d, auto& b) { return fmt::format("fmax({}, {})", d, b); }});
}
Carried difference_walk(Walker& w, const ir::Node& n, const std::string& p) {
  return combine(w, n, p, {Select::First, [](auto& d, auto& b) { return fmt::format("fmax({}, -{})", d, b); }});
}

// render.normals: dual: the gradient of the child whose distance is picked.
Dual union_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  return fold_dual(w, n, p, [&](const Dual& v, const Dual& k) {
    w.line(fmt::format("{} = v3_select({}, {}, {} < {});", v.g, v.g, k.g, k.d, v.d));
    w.line(fmt::format("{} = fmin({}, {});", v.d, v.d, k.d));
  });
}
Dual intersection_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  return fold_dual(w, n, p, [&](const Dual& v, const Dual& k) {
    w.line(fmt::format("{} = v3_select({}, {}, {} > {});", v.g, v.g, k.g, k.d, v.d));
    w.line(fmt::format("{} = fmax({}, {});", v.d, v.d, k.d));
  });
}
Dual difference_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  return fold_dual(w, n, p, [&](const Dual& v, const Dual& k) {
    w.line(fmt::format("{} = v3_select({}, v3_scale({}, -1.0f), -{} > {});", v.g, v.g, k.g, k.d, v.d));
    w.line(fmt::format("{} = fmax({}, -{});", v.d, v.d, k.d));
  });
}

}  // namespace

namespace {
constexpr ParamDoc k_union_docs[] = {
    {"union", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_intersection_docs[] = {
    {"intersection", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_difference_docs[] = {
    {"difference", "list of nodes", "", "at least one", "the shape, then what is cut from it"},
};
}  // namespace

namespace described {
extern const Description Union{.kind = ir::Kind::Union,
                               .yaml = "union",
                               .example = "{union: [{sphere: {radius: 0.45}, translate: [-0.3, 0, 0]}, {box: {size: [0.7, 0.7, 0.7]}, translate: [0.3, 0, 0]}]}",
                               .param_count = 0,
                               .dual_normals = true,
                               .child_props = props<Select::Nearer>,
                               .evaluate = evaluate<Select::Nearer>,
                               .walk = union_walk,
                               .walk_dual = union_dual,
                               .fit_children = true,
                               .summary = "The shapes together: the minimum of the children's distances. The material is the nearest child's.",
                               .docs = k_union_docs};
extern const Description Intersection{.kind = ir::Kind::Intersection,
                                      .yaml = "intersection",
                                      .example = "{intersection: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}",
                                      .param_count = 0,
                                      .dual_normals = true,
                                      .child_props = props<Select::Farther>,
                                      .evaluate = evaluate<Select::Farther>,
                                      .walk = intersection_walk,
                                      .walk_dual = intersection_dual,
                                      .summary = "What the shapes share: the maximum of the children's distances. The material is the farthest child's.",
                                      .docs = k_intersection_docs};
extern const Description Difference{.kind = ir::Kind::Difference,
                                    .yaml = "difference",
                                    .example = "{difference: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.65}}]}",
                                    .param_count = 0,
                                    .dual_normals = true,
                                    .child_props = props<Select::First>,
                                    .evaluate = evaluate<Select::First>,
                                    .walk = difference_walk,
                                    .walk_dual = difference_dual,
                                    .summary = "The first shape with the others cut away; the cut face keeps the first child's material.",
                                    .docs = k_difference_docs};
}

}  // namespace sdfc::kinds
