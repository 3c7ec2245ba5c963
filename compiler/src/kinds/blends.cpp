// blend_union, blend_intersection and blend_difference: the stylised seams
// (hg_sdf, Quilez); intersection and difference are the union's dual,
// -U(-a, -b) and -U(-a, b).
#include "combinator.hpp"
#include "sdfc/kinds/params.hpp"

SDFC_KIND(BlendUnion,         50, "blend_union",         Combinator, -1, "style,radius,steps",           "")
SDFC_KIND(BlendIntersection,  51, "blend_intersection",  Combinator, -1, "style,radius,steps",           "")
SDFC_KIND(BlendDifference,    52, "blend_difference",    Combinator, -1, "style,radius,steps",           "")

namespace sdfc::kinds {
namespace {
using namespace combinator;

// style: 0 cubic, 1 exponential, 2 chamfer, 3 round, 4 columns, 5 stairs;
// steps: the columns' or stairs' count.
struct BlendP {
  double style, radius, steps;
};

// The union-style blend in plain double arithmetic.
double blend_union(int style, double a, double b, double r, double n) {
  switch (style) {
    case 0: {
      double h = std::max(r - std::fabs(a - b), 0.0) / r;
      return std::min(a, b) - h * h * h * r / 6;
    }
    case 1: {
      double m = std::min(a, b);
      return m - r * std::log2(std::exp2((m - a) / r) + std::exp2((m - b) / r));
    }
    case 2: return std::min(std::min(a, b), (a - r + b) * std::sqrt(0.5));
    case 3: return std::max(r, std::min(a, b)) - std::hypot(std::max(r - a, 0.0), std::max(r - b, 0.0));
    case 4: {
      double col = r * std::sqrt(2.0) / ((n - 1) * 2 + std::sqrt(2.0));
      double x = (a + b) * std::sqrt(0.5), y = (b - a) * std::sqrt(0.5);
      x += -std::sqrt(0.5) * r + col * std::sqrt(2.0);
      if (std::fmod(n, 2.0) == 1) y += col;
      double size = 2 * col;
      y = y + size / 2 - size * std::floor((y + size / 2) / size) - size / 2;
      // The columns, cut to the region a < r, b < r (continuously, see blends.cl).
      double cols = std::min(std::hypot(x, y) - col, x);
      return std::min({a, b, std::max(cols, std::max(a, b) - r)});
    }
    case 5: {
      double s = r / n, u = b - r;
      double w = u - a + s, m = 2 * s;
      return std::min(std::min(a, b), 0.5 * (u + a + std::fabs(w - m * std::floor(w / m) - s)));
    }
  }
  return std::min(a, b);
}

template <Select S>
ir::Props props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const BlendP q = view<BlendP>(n);
  ir::Props p = fold_props(n, kid, S, 8);
  // Material is added only by unions, within the blend radius.
  if (S == Select::Nearer && p.bounds.finite()) p.bounds = p.bounds.padded(q.radius);
  // Chamfer, round and columns combine a and b along the diagonal: where
  // the two gradients agree the blend's gradient reaches sqrt(2).
  int style = int(q.style);
  if (style == 2 || style == 3 || style == 4) p.lipschitz *= std::sqrt(2.0);
  if (p.lipschitz > 1) p.cls = ir::DistanceClass::Lipschitz;
  return p;
}

// As blend(a, nb) of the children's own distances, nb being B's distance as
// it enters (negated for a difference). Cubic and exponential mix the
// materials by B's share; the others take the nearer child's (a difference
// keeps the first).
template <Select S>
Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const BlendP q = view<BlendP>(n);
  const int style = int(q.style);
  std::function<double(double, double)> blend = [&](double a, double b) {
    return S == Select::Nearer ? blend_union(style, a, b, q.radius, q.steps) : -blend_union(style, -a, -b, q.radius, q.steps);
  };
  return fold_samples(g, n, p, [&](Sample& acc, const Sample& b) {
    double nb = S == Select::First ? -b.distance : b.distance;
    if (style < 2) mix_sample(acc, b, S, nb, blend);
    else select_sample(acc, b, S, blend(acc.distance, nb));
  });
}

std::string_view weight(const ir::Node& n) {
  double style = view<BlendP>(n).style;
  return style == 0 ? "op_weight_cubic" : style == 1 ? "op_weight_exponential" : "";
}

template <Select S>
Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  static const char* fns[] = {"op_blend_cubic", "op_blend_exponential", "op_blend_chamfer",
                              "op_blend_round", "op_blend_columns",     "op_blend_stairs"};
  const BlendP q = view<BlendP>(n);
  const int style = int(q.style);
  // The union-style blend of a and b; the radius may be animated.
  auto blend = [&, style](const std::string& a, const std::string& b) {
    std::string steps = style >= 4 ? ", " + w.lit().typed(q.steps) : "";
    return fmt::format("{}({}, {}, (real)({}){})", w.call(fns[style]), a, b, w.param(n, SDFC_AT(BlendP, radius)), steps);
  };
  auto fold = [&](const std::string& d, const std::string& b) { return dual_fold(S, d, b, blend); };
  return combine(w, n, p, {S, fold, weight(n)});
}

}  // namespace

int blend_style(const ir::Node& blend) { return int(view<BlendP>(blend).style); }

namespace {
constexpr ParamDoc k_blend_union_docs[] = {
    {"radius", "number", "", "> 0", "the size of the seam"},
    {"steps", "integer", "4", "1 to 1000", "columns and stairs only: how many along the seam"},
    {"children", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_blend_intersection_docs[] = {
    {"radius", "number", "", "> 0", "the size of the edge"},
    {"steps", "integer", "4", "1 to 1000", "columns and stairs only: how many along the edge"},
    {"children", "list of nodes", "", "at least one", "the shapes"},
};
constexpr ParamDoc k_blend_difference_docs[] = {
    {"radius", "number", "", "> 0", "the size of the edge"},
    {"steps", "integer", "4", "1 to 1000", "columns and stairs only: how many along the edge"},
    {"children", "list of nodes", "", "at least one", "the shape, then what is cut from it"},
};
}  // namespace

namespace described {
extern const Description BlendUnion{.kind = ir::Kind::BlendUnion,
                                    .yaml = "blend_union",
                                    .example = "{stairs_union: {radius: 0.3, steps: 4, children: [{box: {size: [1.2, 1.2, 0.3]}}, {cylinder: {radius: 0.25, height: 0.9}, translate: [0, 0, 0.45]}]}}",
                                    .param_count = count_of<BlendP>(),
                                    .child_props = props<Select::Nearer>,
                                    .evaluate = evaluate<Select::Nearer>,
                                    .walk = walk<Select::Nearer>,
                                    .weight = weight,
                                    .summary = "A union with a stylised seam: a 45° bevel (chamfer), a quarter-circle fillet (round), round columns or stairs along the seam.",
                                    .written_as = "`chamfer_union`, `round_union`, `columns_union`, `stairs_union`, or `smooth_union` with `kind: cubic` or `kind: exponential`",
                                    .docs = k_blend_union_docs};
extern const Description BlendIntersection{.kind = ir::Kind::BlendIntersection,
                                           .yaml = "blend_intersection",
                                           .example = "{chamfer_intersection: {radius: 0.15, children: [{sphere: {radius: 0.6}}, {box: {size: [0.9, 0.9, 0.9]}}]}}",
                                           .param_count = count_of<BlendP>(),
                                           .child_props = props<Select::Farther>,
                                           .evaluate = evaluate<Select::Farther>,
                                           .walk = walk<Select::Farther>,
                                           .weight = weight,
                                           .summary = "An intersection with a stylised edge, the union's dual.",
                                           .written_as = "`chamfer_intersection`, `round_intersection`, `columns_intersection`, `stairs_intersection`, or `smooth_intersection` with `kind: cubic` or `kind: exponential`",
                                           .docs = k_blend_intersection_docs};
extern const Description BlendDifference{.kind = ir::Kind::BlendDifference,
                                         .yaml = "blend_difference",
                                         .example = "{columns_difference: {radius: 0.2, steps: 3, children: [{box: {size: [1, 1, 1]}}, {sphere: {radius: 0.6}, translate: [0.45, -0.45, 0.45]}]}}",
                                         .param_count = count_of<BlendP>(),
                                         .child_props = props<Select::First>,
                                         .evaluate = evaluate<Select::First>,
                                         .walk = walk<Select::First>,
                                         .weight = weight,
                                         .summary = "A difference with a stylised cut edge.",
                                         .written_as = "`chamfer_difference`, `round_difference`, `columns_difference`, `stairs_difference`, or `smooth_difference` with `kind: cubic` or `kind: exponential`",
                                         .docs = k_blend_difference_docs};
}

}  // namespace sdfc::kinds
