// smooth_union, smooth_intersection and smooth_difference: the polynomial
// smooth minimum and maximum (Quilez), which round the seam within
// `radius` and mix the children's materials there.
#include "combinator.hpp"
#include "sdfc/kinds/params.hpp"

SDFC_KIND(SmoothUnion,        13, "smooth_union",        Combinator, -1, "radius",                       "op_blend_polynomial")
SDFC_KIND(SmoothIntersection, 14, "smooth_intersection", Combinator, -1, "radius",                       "op_blend_polynomial")
SDFC_KIND(SmoothDifference,   15, "smooth_difference",   Combinator, -1, "radius",                       "op_blend_polynomial")

namespace sdfc::kinds {
namespace {
using namespace combinator;

struct SmoothP {
  double radius;
};

double smin_poly(double a, double b, double k) {
  double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k / 4;
}
double smax_poly(double a, double b, double k) {
  double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::max(a, b) + h * h * k / 4;
}

template <Select S>
ir::Props props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  ir::Props p = fold_props(n, kid, S, 2);
  // A smooth union reaches beyond the union of its children's bounds by
  // up to radius/4 for each fold (ir::smooth_union_reach).
  if (S == Select::Nearer && p.bounds.finite())
    p.bounds = p.bounds.padded(ir::smooth_union_reach(n.children.size(), view<SmoothP>(n).radius));
  return p;
}

// A difference mixes by the share of -b, B's own distance negated.
template <Select S>
Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const double k = view<SmoothP>(n).radius;
  return fold_samples(g, n, p, [k](Sample& acc, const Sample& b) {
    if (S == Select::Nearer)
      mix_sample(acc, b, S, b.distance, [k](double x, double y) { return smin_poly(x, y, k); });
    else
      mix_sample(acc, b, S, S == Select::First ? -b.distance : b.distance,
                 [k](double x, double y) { return smax_poly(x, y, k); });
  });
}

std::string_view weight(const ir::Node&) { return "op_weight_polynomial"; }

template <Select S>
Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  const std::string fn(ir::info(n.kind).stdlib_function);
  std::string radius = w.param(n, SDFC_AT(SmoothP, radius));
  return combine(w, n, p,
                 {S,
                  [&](const std::string& d, const std::string& b) {
                    return dual_fold(S, d, b, [&](const std::string& x, const std::string& y) {
                      return fmt::format("{}({}, {}, {})", w.call(fn), x, y, radius);
                    });
                  },
                  weight(n)});
}

// render.normals: dual: opg_smooth mixes the gradients by the blend's
// weights; a difference is the intersection with the negated child.
template <Select S>
Dual dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  const std::string k = w.real(view<SmoothP>(n).radius);
  w.call("opg_smooth");
  return fold_dual(w, n, p, [&](const Dual& v, const Dual& c) {
    if (S == Select::Nearer) {
      w.line(fmt::format("{} = opg_smooth({}, {}, {}, {}, {}, 1.0f);", v.g, v.d, c.d, v.g, c.g, k));
      w.line(fmt::format("{} = {}({}, {}, {});", v.d, w.call("op_blend_polynomial"), v.d, c.d, k));
    } else if (S == Select::Farther) {
      w.line(fmt::format("{} = opg_smooth({}, {}, {}, {}, {}, -1.0f);", v.g, v.d, c.d, v.g, c.g, k));
      w.line(fmt::format("{} = -{}(-{}, -{}, {});", v.d, w.call("op_blend_polynomial"), v.d, c.d, k));
    } else {
      w.line(fmt::format("{} = opg_smooth({}, -{}, {}, v3_scale({}, -1.0f), {}, -1.0f);", v.g, v.d, c.d, v.g, c.g, k));
      w.line(fmt::format("{} = -{}(-{}, {}, {});", v.d, w.call("op_blend_polynomial"), v.d, c.d, k));
    }
  });
}

}  // namespace

double smooth_radius(const ir::Node& smooth) { return view<SmoothP>(smooth).radius; }

namespace {
constexpr ParamDoc k_smooth_union_docs[] = {
    {"radius", "number", "", "> 0", "how far the blend reaches; may be an expression of time"},
    {"kind", "one of polynomial\\|cubic\\|exponential", "polynomial", "", "the blend's curve (cubic and exponential are `blend_union` nodes)"},
    {"children", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_smooth_intersection_docs[] = {
    {"radius", "number", "", "> 0", "how far the blend reaches; may be an expression of time"},
    {"kind", "one of polynomial\\|cubic\\|exponential", "polynomial", "", "the blend's curve"},
    {"children", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_smooth_difference_docs[] = {
    {"radius", "number", "", "> 0", "how far the blend reaches; may be an expression of time"},
    {"kind", "one of polynomial\\|cubic\\|exponential", "polynomial", "", "the blend's curve"},
    {"children", "list of nodes", "", "at least one", "the shape, then what is cut from it"},
};
}  // namespace

namespace described {
extern const Description SmoothUnion{.kind = ir::Kind::SmoothUnion,
                                     .yaml = "smooth_union",
                                     .example = "{smooth_union: {radius: 0.25, children: [{sphere: {radius: 0.45}, translate: [-0.35, 0, 0]}, {sphere: {radius: 0.35}, translate: [0.35, 0, 0.1]}]}}",
                                     .param_count = count_of<SmoothP>(),
                                     .dual_normals = true,
                                     .child_props = props<Select::Nearer>,
                                     .evaluate = evaluate<Select::Nearer>,
                                     .walk = walk<Select::Nearer>,
                                     .weight = weight,
                                     .walk_dual = dual<Select::Nearer>,
                                     .fit_children = true,
                                     .summary = "A union whose seams blend within `radius` (a polynomial smooth minimum); materials mix by each child's share of the blend.",
                                     .docs = k_smooth_union_docs};
extern const Description SmoothIntersection{.kind = ir::Kind::SmoothIntersection,
                                            .yaml = "smooth_intersection",
                                            .example = "{smooth_intersection: {radius: 0.15, children: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}}",
                                            .param_count = count_of<SmoothP>(),
                                            .dual_normals = true,
                                            .child_props = props<Select::Farther>,
                                            .evaluate = evaluate<Select::Farther>,
                                            .walk = walk<Select::Farther>,
                                            .weight = weight,
                                            .walk_dual = dual<Select::Farther>,
                                            .summary = "An intersection whose edges are rounded within `radius`.",
                                            .docs = k_smooth_intersection_docs};
extern const Description SmoothDifference{.kind = ir::Kind::SmoothDifference,
                                          .yaml = "smooth_difference",
                                          .example = "{smooth_difference: {radius: 0.1, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.65}}]}}",
                                          .param_count = count_of<SmoothP>(),
                                          .dual_normals = true,
                                          .child_props = props<Select::First>,
                                          .evaluate = evaluate<Select::First>,
                                          .walk = walk<Select::First>,
                                          .weight = weight,
                                          .walk_dual = dual<Select::First>,
                                          .summary = "A difference whose cut edges are rounded within `radius`; the cut face takes the second child's material.",
                                          .docs = k_smooth_difference_docs};
}

}  // namespace sdfc::kinds
