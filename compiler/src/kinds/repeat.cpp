// repeat and polar_repeat: the child in its own cell and the nearest
// neighbouring cell, so a child reaching across the border leaves no seam.
#include <numbers>
#include <vector>

#include "domain_op.hpp"

SDFC_KIND(Repeat,             38, "repeat",              Transform,  1, "px,py,pz,nx,ny,nz",             "")
SDFC_KIND(PolarRepeat,        40, "polar_repeat",        Transform,  1, "axis,count",                    "")

namespace sdfc::kinds {
namespace {
using namespace domain;

// A count of 0 repeats without end; 1 leaves that axis alone.
struct RepeatP {
  V3 period, count;
};
// axis: 0 = x, 1 = y, 2 = z
struct PolarRepeatP {
  double axis, count;
};

ir::Props repeat_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const RepeatP q = view<RepeatP>(n);
  ir::Props p = kid(0);
  need_bounds(n, p.bounds, "repeat");
  const Box3 cell = p.bounds;
  int repeated = 0;
  for (int i = 0; i < 3; ++i) {
    if (q.count[i] == 1) continue;
    ++repeated;
    const char* axis = i == 0 ? "x" : i == 1 ? "y" : "z";
    // The neighbour cell is evaluated, so the child may reach into it, not past it.
    if (reach(cell, i) >= q.period[i])
      fail(n.loc, fmt::format("repeat: along {} the shape reaches {:.4g} from its cell centre, not less than the "
                              "period {:.4g}", axis, reach(cell, i), q.period[i]),
           "make the period larger than the shape's half width along that axis");
    if (q.count[i] == 0) {
      p.bounds.lo[i] = -Box3::inf(), p.bounds.hi[i] = Box3::inf();
    } else {
      double half = q.period[i] * (q.count[i] - 1) / 2;
      p.bounds.lo[i] -= half, p.bounds.hi[i] += half;
    }
  }
  p.cls = worse(p.cls, DistanceClass::Bound);
  p.cost = p.cost * (1 << repeated) + 12 * repeated;
  return p;
}

// Own cell and its neighbour on each repeated axis, plus the bound on every farther copy.
Sample repeat_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const RepeatP q = view<RepeatP>(n);
  const Box3& cb = g.node(n.children[0]).props.bounds;
  std::vector<double> opts[3];
  double rest = 1e300;
  for (int i = 0; i < 3; ++i) {
    double s = q.period[i], cnt = q.count[i];
    if (cnt == 1) {
      opts[i] = {p[i]};
      continue;
    }
    double half = cnt > 0 ? (cnt - 1) / 2 : 0;
    // std::round rounds halves away from zero, as OpenCL's round does.
    double cell = std::round(p[i] / s + half);
    if (cnt > 0) cell = std::clamp(cell, 0.0, cnt - 1);
    double u = p[i] - s * (cell - half);
    double side = u < 0 ? -1 : 1;
    if (cnt > 0 && (cell + side < 0 || cell + side > cnt - 1)) side = -side;
    opts[i] = {u, p[i] - s * (cell + side - half)};
    rest = std::min(rest, s - reach(cb, i) + std::fabs(u));
  }
  std::vector<V3> points;
  for (double x : opts[0])
    for (double y : opts[1])
      for (double z : opts[2]) points.push_back({x, y, z});
  Sample best = nearest_at(g, n, points);
  best.distance = std::min(best.distance, rest);
  return best;
}

// The child in the point's own cell and in the neighbouring cell on each
// repeated axis (2^k evaluations); every other copy is at least
// period - reach + |u| away along some axis, which bounds the rest.
Carried repeat_walk(Walker& w, const ir::Node& n, const std::string& p) {
  const RepeatP q = view<RepeatP>(n);
  const ir::Box3& cb = w.graph().node(n.children[0]).props.bounds;
  const codegen::detail::Literals& lit = w.lit();
  const char* xyz[] = {"x", "y", "z"};
  std::string own[3], near[3], rest;
  std::vector<int> axes;
  w.line("// " + w.describe(n));
  for (int i = 0; i < 3; ++i) {
    own[i] = p + "." + xyz[i];
    near[i] = own[i];
    if (q.count[i] == 1) continue;
    axes.push_back(i);
    own[i] = w.var("u"), near[i] = w.var("nb");
    w.line(fmt::format("real {};", near[i]));
    w.line(fmt::format("real {} = {}({}.{}, {}, {}, &{});", own[i], w.call("dm_repeat_axis"), p, xyz[i],
                       lit.typed(q.period[i]), lit.typed(q.count[i]), near[i]));
    std::string term = fmt::format("{} + fabs({})", lit.real(q.period[i] - reach(cb, i)), own[i]);
    rest = rest.empty() ? term : fmt::format("fmin({}, {})", rest, term);
  }
  std::vector<std::string> points;
  for (int c = 0; c < (1 << axes.size()); ++c) {
    std::string comp[3] = {own[0], own[1], own[2]};
    for (size_t a = 0; a < axes.size(); ++a)
      if (c & (1 << a)) comp[axes[a]] = near[axes[a]];
    points.push_back(fmt::format("v3({}, {}, {})", comp[0], comp[1], comp[2]));
  }
  Carried v = w.cells(n, points);
  std::string d = w.var("d");
  w.line(fmt::format("real {} = fmin({}, {});  // copies beyond the neighbours are farther", d, v.d, rest));
  return with_d(v, d);
}

ir::Props polar_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const int axis = int(view<PolarRepeatP>(n).axis);
  ir::Props p = kid(0);
  need_bounds(n, p.bounds, "polar_repeat");
  p.bounds = around_axis(p.bounds, axis, radial(p.bounds, axis));
  p.cls = worse(p.cls, DistanceClass::Bound);
  p.cost = p.cost * 2 + 40;
  return p;
}

Sample polar_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const PolarRepeatP q = view<PolarRepeatP>(n);
  int axis = int(q.axis);
  V3 l = to_z(p, axis);
  double sector = 2 * std::numbers::pi / q.count;
  double a = std::atan2(l[1], l[0]), r = std::hypot(l[0], l[1]);
  double i = std::round(a / sector);
  double j = i + (a - i * sector < 0 ? -1 : 1);
  std::vector<V3> points;
  for (double cell : {i, j}) {
    double t = a - cell * sector;
    points.push_back(from_z({r * std::cos(t), r * std::sin(t), l[2]}, axis));
  }
  return nearest_at(g, n, points);
}

Carried polar_walk(Walker& w, const ir::Node& n, const std::string& p) {
  std::string near = w.var("p"), own = w.var("p");
  w.line(fmt::format("vec3 {};  // {}", near, w.describe(n)));
  w.line(fmt::format("vec3 {} = {}({}, {}, {}, &{});", own, w.call("dm_polar"), p, int(view<PolarRepeatP>(n).axis),
                     w.param(n, SDFC_AT(PolarRepeatP, count)), near));
  return w.cells(n, {own, near});
}

}  // namespace

namespace {
constexpr ParamDoc k_polar_repeat_docs[] = {
    {"axis", "one of x|y|z", "z", "", "the axis it repeats around"},
    {"count", "integer", "", "2 to 10000", "how many copies"},
};
constexpr ParamDoc k_repeat_docs[] = {
    {"period", "vec3", "", ">= 0", "the spacing along x, y and z; 0: not repeated along that axis"},
    {"count", "list of 3 integers", "(endless)", "each 1 to 100000", "copies per axis"},
};
}  // namespace

namespace described {
extern const Description Repeat{.kind = ir::Kind::Repeat,
                                .yaml = "repeat",
                                .example = "{sphere: {radius: 0.2}, repeat: {period: [0.5, 0.5, 0.5], count: [3, 3, 1]}}",
                                .param_count = count_of<RepeatP>(),
                                .child_props = repeat_props,
                                .evaluate = repeat_evaluate,
                                .walk = repeat_walk,
                                .summary = "Copies the node on a grid, endless or `count` copies per axis centred on the origin. The child must reach less than one period from its cell's centre.",
                                .written_as = "`repeat: {period, count}` on any bounded node",
                                .docs = k_repeat_docs};
extern const Description PolarRepeat{.kind = ir::Kind::PolarRepeat,
                                     .yaml = "polar_repeat",
                                     .example = "{union: [{box: {size: [0.15, 0.3, 0.5]}, translate: [0.7, 0, 0]}], polar_repeat: {axis: z, count: 8}}",
                                     .param_count = count_of<PolarRepeatP>(),
                                     .child_props = polar_props,
                                     .evaluate = polar_evaluate,
                                     .walk = polar_walk,
                                     .summary = "Copies the node around an axis; the child should stay within its own sector.",
                                     .written_as = "`polar_repeat: {axis, count}` on any bounded node",
                                     .docs = k_polar_repeat_docs};
}

}  // namespace sdfc::kinds
