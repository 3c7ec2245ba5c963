// elongate and scale_xyz: the child stretched, by inserting a slab at its
// centre (elongate) or by a factor per axis (scale_xyz).
#include "domain_op.hpp"

SDFC_KIND(Elongate,           44, "elongate",            Transform,  1, "hx,hy,hz",                      "")
SDFC_KIND(ScaleXYZ,           49, "scale_xyz",           Transform,  1, "sx,sy,sz",                      "")

namespace sdfc::kinds {
namespace {
using namespace domain;

// The half lengths of the slab inserted along each axis.
struct ElongateP {
  V3 half;
};
struct ScaleXYZP {
  V3 factor;
};

ir::Props elongate_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const V3 h = view<ElongateP>(n).half;
  ir::Props p = bound_of(kid, 8);
  for (int i = 0; i < 3; ++i) p.bounds.lo[i] -= h[i], p.bounds.hi[i] += h[i];
  return p;
}

Sample elongate_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const V3 h = view<ElongateP>(n).half;
  return child_at(g, n, {p[0] - std::clamp(p[0], -h[0], h[0]), p[1] - std::clamp(p[1], -h[1], h[1]),
                         p[2] - std::clamp(p[2], -h[2], h[2])});
}

Carried elongate_walk(Walker& w, const ir::Node& n, const std::string& p) {
  const V3 h = view<ElongateP>(n).half;
  auto axis = [&](int i, const char* c) {
    return fmt::format("{0}.{1} - clamp({0}.{1}, K({2}), K({3}))", p, c, w.lit().real(-h[i]), w.param(n, size_t(i)));
  };
  return w.child(n.children[0], w.point(n, fmt::format("v3({}, {}, {})", axis(0, "x"), axis(1, "y"), axis(2, "z"))));
}

ir::Props scale_xyz_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const V3 f = view<ScaleXYZP>(n).factor;
  ir::Props p = bound_of(kid, 6);
  for (int i = 0; i < 3; ++i) p.bounds.lo[i] *= f[i], p.bounds.hi[i] *= f[i];
  return p;
}

// The smallest factor keeps the distance a bound.
Sample scale_xyz_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const V3 f = view<ScaleXYZP>(n).factor;
  Sample s = child_at(g, n, {p[0] / f[0], p[1] / f[1], p[2] / f[2]});
  s.distance = s.distance * std::min({f[0], f[1], f[2]});
  return s;
}

Carried scale_xyz_walk(Walker& w, const ir::Node& n, const std::string& p) {
  const V3 f = view<ScaleXYZP>(n).factor;
  std::string p2 = w.point(n, fmt::format("v3_mul({}, {})", p, w.lit().vec3({1 / f[0], 1 / f[1], 1 / f[2]})));
  Carried c = w.child(n.children[0], p2);
  std::string d = w.var("d");
  w.line(fmt::format("real {} = {} * {};  // the smallest factor keeps it a bound", d, c.d,
                     w.lit().real(std::min({f[0], f[1], f[2]}))));
  return with_d(c, d);
}

}  // namespace

namespace {
constexpr ParamDoc k_scale_x_y_z_docs[] = {
    {"scale", "vec3", "", "each > 0, at most 10000", "the factors along x, y and z"},
};
constexpr ParamDoc k_elongate_docs[] = {
    {"elongate", "vec3", "", ">= 0", "the total stretch along x, y and z"},
};
}  // namespace

namespace described {
extern const Description Elongate{.kind = ir::Kind::Elongate,
                                  .yaml = "elongate",
                                  .example = "{sphere: {radius: 0.35}, elongate: [0.8, 0, 0.4]}",
                                  .param_count = count_of<ElongateP>(),
                                  .child_props = elongate_props,
                                  .evaluate = elongate_evaluate,
                                  .walk = elongate_walk,
                                  .summary = "Pulls the node apart at its centre along each axis, filling the gap with its cross-section.",
                                  .written_as = "`elongate: [x, y, z]` on any node",
                                  .docs = k_elongate_docs};
extern const Description ScaleXYZ{.kind = ir::Kind::ScaleXYZ,
                                  .yaml = "scale_xyz",
                                  .example = "{sphere: {radius: 0.5}, scale: [1.6, 1, 0.6]}",
                                  .param_count = count_of<ScaleXYZP>(),
                                  .child_props = scale_xyz_props,
                                  .evaluate = scale_xyz_evaluate,
                                  .walk = scale_xyz_walk,
                                  .summary = "Scales the node by a factor per axis; the distance is multiplied by the smallest factor, a bound.",
                                  .written_as = "`scale: [sx, sy, sz]` on any node",
                                  .docs = k_scale_x_y_z_docs};
}

}  // namespace sdfc::kinds
