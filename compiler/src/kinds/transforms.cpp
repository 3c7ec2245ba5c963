// translate, rotate, scale and step_factor: the rigid moves and the uniform
// scale (the distance scaled back), and the fudge factor on the distance.
#include "domain_op.hpp"
#include "sdfc/kinds/folding.hpp"
#include "sdfc/kinds/params.hpp"

SDFC_KIND(Translate,          7, "translate",           Transform,  1, "x,y,z",                         "")
SDFC_KIND(Rotate,             8, "rotate",              Transform,  1, "m00,m01,m02,m10,m11,m12,m20,m21,m22", "")
SDFC_KIND(Scale,              9, "scale",               Transform,  1, "s",                             "")
// The child's distance times `factor` (a `step_factor:` modifier).
SDFC_KIND(StepFactor,         53, "step_factor",         Transform,  1, "factor",                        "")

namespace sdfc::kinds {
namespace {
using namespace domain;

struct TranslateP {
  V3 by;
};
// Local to world, row by row; the point takes the transpose.
struct RotateP {
  double m[9];
};
struct ScaleP {
  double s;
};
struct StepFactorP {
  double factor;
};

ir::Props translate_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const V3 t = view<TranslateP>(n).by;
  ir::Props p = kid(0);
  for (int i = 0; i < 3; ++i) p.bounds.lo[i] += t[i], p.bounds.hi[i] += t[i];
  p.cost += 3;
  return p;
}
Sample translate_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const V3 t = view<TranslateP>(n).by;
  return child_at(g, n, {p[0] - t[0], p[1] - t[1], p[2] - t[2]});
}
Carried translate_walk(Walker& w, const ir::Node& n, const std::string& p) {
  return w.child(n.children[0], w.point(n, fmt::format("v3_sub({}, {})", p, w.param3(n, SDFC_AT(TranslateP, by)))));
}

// An identity vanishes; nested translations add up.
ir::NodeId translate_fold(const Folding& f) {
  const V3 t = view<TranslateP>(f.params).by;
  if (t[0] == 0 && t[1] == 0 && t[2] == 0) return f.kids[0];
  if (!f.merge || f.child(0).kind != ir::Kind::Translate) return ir::kNoNode;
  const ir::Node& c = f.child(0);
  const V3 u = view<TranslateP>(c).by;
  return f.again(params_of(TranslateP{{t[0] + u[0], t[1] + u[1], t[2] + u[2]}}), c.children);
}
Dual translate_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  const V3 t = view<TranslateP>(n).by;
  std::string p2 = w.var("p");
  w.line(fmt::format("vec3 {} = v3_sub({}, {});", p2, p, w.lit().vec3(t)));
  return w.child(n.children[0], p2);
}

ir::Props rotate_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const RotateP r = view<RotateP>(n);
  ir::Props p = kid(0);
  p.cost += 15;
  const Box3 b = p.bounds;
  if (!b.finite()) {
    p.bounds = Box3::everything();
    return p;
  }
  p.bounds = {{Box3::inf(), Box3::inf(), Box3::inf()}, {-Box3::inf(), -Box3::inf(), -Box3::inf()}};
  for (int corner = 0; corner < 8; ++corner) {
    double c[3] = {corner & 1 ? b.hi[0] : b.lo[0], corner & 2 ? b.hi[1] : b.lo[1], corner & 4 ? b.hi[2] : b.lo[2]};
    for (int i = 0; i < 3; ++i) {
      double v = r.m[i * 3] * c[0] + r.m[i * 3 + 1] * c[1] + r.m[i * 3 + 2] * c[2];
      p.bounds.lo[i] = std::min(p.bounds.lo[i], v);
      p.bounds.hi[i] = std::max(p.bounds.hi[i], v);
    }
  }
  return p;
}
Sample rotate_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const RotateP r = view<RotateP>(n);
  const double* q = r.m;  // in the order of the table row
  return child_at(g, n, {q[0] * p[0] + q[3] * p[1] + q[6] * p[2], q[1] * p[0] + q[4] * p[1] + q[7] * p[2],
                         q[2] * p[0] + q[5] * p[1] + q[8] * p[2]});
}
Carried rotate_walk(Walker& w, const ir::Node& n, const std::string& p) {
  auto r = [&](size_t i) { return w.param(n, i); };
  return w.child(n.children[0], w.point(n, fmt::format("v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {})", p, r(0), r(3),
                                                       r(6), r(1), r(4), r(7), r(2), r(5), r(8))));
}

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
ir::NodeId rotate_fold(const Folding& f) {
  if (is_identity(f.params)) return f.kids[0];
  if (!f.merge || f.child(0).kind != ir::Kind::Rotate) return ir::kNoNode;
  return f.again(mat_mul(f.params, f.child(0).params), f.child(0).children);
}
// The point goes world->local (the transpose), the gradient local->world.
Dual rotate_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  auto r = [&](size_t i) { return w.real(view<RotateP>(n).m[i]); };
  std::string p2 = w.var("p");
  w.line(fmt::format("vec3 {} = v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {});", p2, p, r(0), r(3), r(6), r(1), r(4),
                     r(7), r(2), r(5), r(8)));
  Dual c = w.child(n.children[0], p2);
  std::string g = w.var("g");
  w.line(fmt::format("vec3 {} = v3_mat({}, {}, {}, {}, {}, {}, {}, {}, {}, {});", g, c.g, r(0), r(1), r(2), r(3), r(4),
                     r(5), r(6), r(7), r(8)));
  return {c.d, g};
}

ir::Props scale_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const double s = view<ScaleP>(n).s;
  ir::Props p = kid(0);
  for (int i = 0; i < 3; ++i) p.bounds.lo[i] *= s, p.bounds.hi[i] *= s;
  p.cost += 4;
  return p;
}
Sample scale_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const double s = view<ScaleP>(n).s;
  Sample c = child_at(g, n, {p[0] / s, p[1] / s, p[2] / s});
  c.distance *= s;
  return c;
}
Carried scale_walk(Walker& w, const ir::Node& n, const std::string& p) {
  const std::string s = w.param(n, SDFC_AT(ScaleP, s));
  std::string inv = n.animated() ? fmt::format("{} / {}", w.lit().real(1.0), s) : w.lit().real(1.0 / view<ScaleP>(n).s);
  Carried c = w.child(n.children[0], w.point(n, fmt::format("v3_scale({}, {})", p, inv)));
  std::string d = w.var("d");
  w.line(fmt::format("real {} = {} * {};  // undo the scale on the distance", d, c.d, s));
  return with_d(c, d);
}

ir::NodeId scale_fold(const Folding& f) {
  const double s = view<ScaleP>(f.params).s;
  if (s == 1) return f.kids[0];
  if (!f.merge || f.child(0).kind != ir::Kind::Scale) return ir::kNoNode;
  return f.again(params_of(ScaleP{s * view<ScaleP>(f.child(0)).s}), f.child(0).children);
}
// d(p) = s d_c(p / s): the gradient is the child's.
Dual scale_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  const double s = view<ScaleP>(n).s;
  std::string p2 = w.var("p");
  w.line(fmt::format("vec3 {} = v3_scale({}, {});", p2, p, w.real(1.0 / s)));
  Dual c = w.child(n.children[0], p2);
  std::string d = w.var("d");
  w.line(fmt::format("real {} = {} * {};", d, c.d, w.real(s)));
  return {d, c.g};
}

// A factor <= 1 keeps a bound a bound; above 1 nothing is promised.
ir::Props step_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  ir::Props p = kid(0);
  if (view<StepFactorP>(n).factor > 1) p.cls = worse(p.cls, DistanceClass::Estimate);
  p.cost += 1;
  return p;
}
Sample step_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  Sample s = child_at(g, n, p);
  s.distance *= view<StepFactorP>(n).factor;
  return s;
}
Carried step_walk(Walker& w, const ir::Node& n, const std::string& p) {
  Carried c = w.child(n.children[0], p);
  std::string d = w.var("d");
  w.line(fmt::format("real {} = {} * {};  // {}", d, c.d, w.param(n, SDFC_AT(StepFactorP, factor)), w.describe(n)));
  return with_d(c, d);
}

Dual step_dual(DualWalker& w, const ir::Node& n, const std::string& p) {
  const std::string f = w.real(view<StepFactorP>(n).factor);
  Dual c = w.child(n.children[0], p);
  std::string d = w.var("d"), g = w.var("g");
  w.line(fmt::format("real {} = {} * {};", d, c.d, f));
  w.line(fmt::format("vec3 {} = v3_scale({}, {});", g, c.g, f));
  return {d, g};
}

}  // namespace

std::array<double, 3> translation(const ir::Node& translate) { return view<TranslateP>(translate).by; }
double scale_factor(const std::vector<double>& scale_params) { return view<ScaleP>(scale_params).s; }
double step_factor(const ir::Node& step) { return view<StepFactorP>(step).factor; }

namespace {
constexpr ParamDoc k_translate_docs[] = {
    {"translate", "vec3", "", "", "the offset; each component may be an expression of time"},
};
constexpr ParamDoc k_rotate_docs[] = {
    {"axis", "vec3", "", "not zero", "the axis (any length)"},
    {"degrees", "number", "", "-36000 to 36000", "the angle, counter-clockwise looking down the axis; may be an expression of time"},
};
constexpr ParamDoc k_scale_docs[] = {
    {"scale", "number", "", "> 0, at most 10000", "the factor; may be an expression of time"},
};
constexpr ParamDoc k_step_factor_docs[] = {
    {"step_factor", "number", "(the fractal's own; 1 for other nodes)", "> 0, at most 2", "the factor on this node's distance"},
};
}  // namespace

namespace described {
extern const Description Translate{.kind = ir::Kind::Translate,
                                   .yaml = "translate",
                                   .example = "{union: [{sphere: {radius: 0.15}}, {box: {size: [0.5, 0.5, 0.5]}, translate: [0.7, 0, 0.3]}]}",
                                   .param_count = count_of<TranslateP>(),
                                   .dual_normals = true,
                                   .child_props = translate_props,
                                   .evaluate = translate_evaluate,
                                   .walk = translate_walk,
                                   .walk_dual = translate_dual,
                                   .fold = translate_fold,
                                   .summary = "Moves the node.",
                                   .written_as = "`translate: [x, y, z]` on any node",
                                   .docs = k_translate_docs};
extern const Description Rotate{.kind = ir::Kind::Rotate,
                                .yaml = "rotate",
                                .example = "{box: {size: [1, 0.5, 0.3]}, rotate: {axis: [0, 0, 1], degrees: 30}}",
                                .param_count = count_of<RotateP>(),
                                .dual_normals = true,
                                .child_props = rotate_props,
                                .evaluate = rotate_evaluate,
                                .walk = rotate_walk,
                                .walk_dual = rotate_dual,
                                .fold = rotate_fold,
                                .summary = "Turns the node about an axis through the origin.",
                                .written_as = "`rotate: {axis: [x, y, z], degrees: a}` or `rotate: [rx, ry, rz]` on any node",
                                .docs = k_rotate_docs};
extern const Description Scale{.kind = ir::Kind::Scale,
                               .yaml = "scale",
                               .example = "{torus: {major_radius: 0.5, minor_radius: 0.15}, scale: 1.5}",
                               .param_count = count_of<ScaleP>(),
                               .dual_normals = true,
                               .child_props = scale_props,
                               .evaluate = scale_evaluate,
                               .walk = scale_walk,
                               .walk_dual = scale_dual,
                               .fold = scale_fold,
                               .summary = "Scales the node uniformly; the distance is scaled with it, so it stays exact.",
                               .written_as = "`scale: s` on any node",
                               .docs = k_scale_docs};
extern const Description StepFactor{.kind = ir::Kind::StepFactor,
                                    .yaml = "step_factor",
                                    .example = "{mandelbulb: {power: 8}, step_factor: 0.8}",
                                    .param_count = count_of<StepFactorP>(),
                                    .dual_normals = true,
                                    .child_props = step_props,
                                    .evaluate = step_evaluate,
                                    .walk = step_walk,
                                    .walk_dual = step_dual,
                                    .fit_children = true,
                                    .summary = "The node's distance times `f`: below 1 it makes an overshooting estimator safe, at the cost of more steps.",
                                    .written_as = "`step_factor: f` on any node",
                                    .docs = k_step_factor_docs};
}

}  // namespace sdfc::kinds
