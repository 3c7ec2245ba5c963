// twist and bend: the point turned by rate * its coordinate along the axis.
// They stretch space, so their Lipschitz constant exceeds 1 (the kernel
// divides by it inside their region).
#include "domain_op.hpp"

SDFC_KIND(Twist,              42, "twist",               Transform,  1, "axis,rate",                     "")
SDFC_KIND(Bend,               43, "bend",                Transform,  1, "axis,rate",                     "")

namespace sdfc::kinds {
namespace {
using namespace domain;

// axis: 0 = x, 1 = y, 2 = z; rate in radians per unit.
struct TurnP {
  double axis, rate;
};

// Twist turns the cross-section by rate * t: at distance rho from the axis
// the map's Jacobian has norm kr/2 + sqrt(1 + (kr/2)^2) with kr = |rate| *
// rho (the largest singular value of [[R, k R J v], [0, 1]]).
double twist_lipschitz(double rate, double rho) {
  double h = std::fabs(rate) * rho / 2;
  return h + std::sqrt(1 + h * h);
}

// Twist turns about the axis, bend turns the (axis, next) plane about the
// third axis: both keep the distance from that axis.
ir::Props turn_props(const ir::Node& n, const Kid& kid, bool twist) {
  const TurnP q = view<TurnP>(n);
  ir::Props p = kid(0);
  int axis = int(q.axis);
  need_bounds(n, p.bounds, ir::info(n.kind).name);
  int keep = twist ? axis : (axis + 2) % 3;
  p.bounds = around_axis(p.bounds, keep, radial(p.bounds, keep));
  p.lipschitz_region = steep_region(p.bounds);
  double rho = radial(p.lipschitz_region, keep);  // the region's farthest point from that axis
  p.lipschitz *= twist ? twist_lipschitz(q.rate, rho) : 1 + std::fabs(q.rate) * rho;
  p.cls = p.lipschitz > 1 ? DistanceClass::Lipschitz : worse(p.cls, DistanceClass::Bound);
  p.cost += 30;
  return p;
}
ir::Props twist_props(const ir::Graph&, const ir::Node& n, const Kid& kid) { return turn_props(n, kid, true); }
ir::Props bend_props(const ir::Graph&, const ir::Node& n, const Kid& kid) { return turn_props(n, kid, false); }

Sample twist_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const TurnP q = view<TurnP>(n);
  int axis = int(q.axis);
  V3 l = to_z(p, axis);
  double t = -q.rate * l[2];
  return child_at(g, n, from_z({std::cos(t) * l[0] - std::sin(t) * l[1], std::sin(t) * l[0] + std::cos(t) * l[1], l[2]}, axis));
}

// Quilez's bend of a bar along the axis: the (axis, next axis) plane turns by rate * t.
Sample bend_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const TurnP q = view<TurnP>(n);
  int axis = int(q.axis), next = (axis + 1) % 3;
  double t = q.rate * p[axis], c = std::cos(t), s = std::sin(t);
  V3 l = p;
  l[axis] = c * p[axis] - s * p[next];
  l[next] = s * p[axis] + c * p[next];
  return child_at(g, n, l);
}

Carried turn_walk(Walker& w, const ir::Node& n, const std::string& p, const char* fn) {
  std::string p2 = w.point(
      n, fmt::format("{}({}, {}, {})", w.call(fn), p, int(view<TurnP>(n).axis), w.param(n, SDFC_AT(TurnP, rate))));
  return w.child(n.children[0], p2);
}
Carried twist_walk(Walker& w, const ir::Node& n, const std::string& p) { return turn_walk(w, n, p, "dm_twist"); }
Carried bend_walk(Walker& w, const ir::Node& n, const std::string& p) { return turn_walk(w, n, p, "dm_bend"); }

}  // namespace

namespace {
constexpr ParamDoc k_twist_docs[] = {
    {"axis", "one of x|y|z", "z", "", "the axis it twists about"},
    {"rate", "number", "", "-1000 to 1000", "radians per unit along the axis"},
};
constexpr ParamDoc k_bend_docs[] = {
    {"axis", "one of x|y|z", "z", "", "the axis of the bar"},
    {"rate", "number", "", "-1000 to 1000", "the curvature: radians per unit along the axis"},
};
}  // namespace

namespace described {
extern const Description Twist{.kind = ir::Kind::Twist,
                               .yaml = "twist",
                               .example = "{box: {size: [0.5, 0.5, 1.6]}, twist: {axis: z, rate: 1.5}}",
                               .param_count = count_of<TurnP>(),
                               .child_props = twist_props,
                               .evaluate = twist_evaluate,
                               .walk = twist_walk,
                               .summary = "Turns each slice across the axis by `rate` radians per unit along it. Lipschitz: corrected where it is steeper than 1.",
                               .written_as = "`twist: {axis, rate}` on any bounded node",
                               .docs = k_twist_docs};
extern const Description Bend{.kind = ir::Kind::Bend,
                              .yaml = "bend",
                              .example = "{box: {size: [1.6, 0.3, 0.3]}, bend: {axis: x, rate: 0.6}}",
                              .param_count = count_of<TurnP>(),
                              .child_props = bend_props,
                              .evaluate = bend_evaluate,
                              .walk = bend_walk,
                              .summary = "Bends a bar along `axis` towards the next axis (x towards y, y towards z, z towards x). Lipschitz: corrected where it is steeper than 1.",
                              .written_as = "`bend: {axis, rate}` on any bounded node",
                              .docs = k_bend_docs};
}

}  // namespace sdfc::kinds
