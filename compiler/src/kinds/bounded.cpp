// bounded: inserted by the insert_bounding_volumes pass, never written by
// users. The box's distance stands in for the child's where it exceeds
// `margin` (a lower bound of the child's distance, since the child's
// surface lies inside the box), so the child is skipped there.
#include "domain_op.hpp"

SDFC_KIND(Bounded,            17, "bounded",             Transform,  1, "lox,loy,loz,hix,hiy,hiz,margin", "sd_box")

namespace sdfc::kinds {
namespace {
using namespace domain;

struct BoundedP {
  V3 lo, hi;
  double margin;
};

ir::Props props(const ir::Graph&, const ir::Node&, const Kid& kid) {
  ir::Props p = kid(0);
  p.cost += 16;  // the box test in front
  return p;
}

Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const BoundedP q = view<BoundedP>(n);
  double c[3], h[3];
  for (int i = 0; i < 3; ++i) c[i] = 0.5 * (q.lo[i] + q.hi[i]), h[i] = 0.5 * (q.hi[i] - q.lo[i]);
  double dx = std::fabs(p[0] - c[0]) - h[0], dy = std::fabs(p[1] - c[1]) - h[1], dz = std::fabs(p[2] - c[2]) - h[2];
  double mx = std::max(dx, 0.0), my = std::max(dy, 0.0), mz = std::max(dz, 0.0);
  double box = std::sqrt(mx * mx + my * my + mz * mz) + std::min(std::max({dx, dy, dz}), 0.0);
  if (box > q.margin) return {box, 0};
  return child_at(g, n, p);
}

// Skips the subtree while every lane is farther from its box than the
// margin. scene_material runs once per hit: no box test there.
Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  if (w.carries_records()) return w.child(n.children[0], p);
  const BoundedP q = view<BoundedP>(n);
  const codegen::detail::Literals& lit = w.lit();
  const bool with_mat = w.tracks_material();
  const std::string margin = w.param(n, SDFC_AT(BoundedP, margin));
  V3 c, h;
  for (int i = 0; i < 3; ++i) c[i] = 0.5 * (q.lo[i] + q.hi[i]), h[i] = 0.5 * (q.hi[i] - q.lo[i]);
  std::string b = w.var("b"), d = w.var("d"), m = with_mat ? w.var("m") : "";
  w.line(fmt::format("real {} = {}(v3_sub({}, {}), {}, {});  // bounding box{}", b, w.call("sd_box"), p, lit.vec3(c),
                     lit.vec3(h), lit.real(0), w.where(n)));
  w.line(fmt::format("real {} = {};", d, b));
  if (with_mat) w.line(fmt::format("real {} = {};", m, lit.typed(0)));
  w.line(fmt::format("if (M_ANY({} <= {}))", b, margin));
  w.open("{");
  Carried inner = w.child(n.children[0], p);
  w.line(fmt::format("{} = SEL({}, {}, {} > {});", d, inner.d, b, b, margin));
  if (with_mat) w.line(fmt::format("{} = SEL({}, {}, {} > {});", m, inner.mat, lit.typed(0), b, margin));
  w.close("}");
  return {d, m};
}

// At a hit the point is inside the margin: the distance and gradient are the child's.
Dual dual(DualWalker& w, const ir::Node& n, const std::string& p) { return w.child(n.children[0], p); }

}  // namespace

namespace described {
extern const Description Bounded{.kind = ir::Kind::Bounded,
                                 .yaml = "bounded",
                                 .param_count = count_of<BoundedP>(),
                                 .dual_normals = true,
                                 .child_props = props,
                                 .evaluate = evaluate,
                                 .walk = walk,
                                 .walk_dual = dual,
                                 .fit_children = true};
}

}  // namespace sdfc::kinds
