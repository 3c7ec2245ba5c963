// mirror and symmetry: the point folded into one chamber, so the child
// shows in each mirror image of it.
#include "domain_op.hpp"

SDFC_KIND(Mirror,             39, "mirror",              Transform,  1, "x,y,z",                         "")
SDFC_KIND(Symmetry,           41, "symmetry",            Transform,  1, "octahedral",                    "")

namespace sdfc::kinds {
namespace {
using namespace domain;

// Per axis: nonzero mirrors it (p becomes |p| there).
struct MirrorP {
  V3 axes;
};
// Nonzero: octahedral (48 chambers), else tetrahedral (24).
struct SymmetryP {
  double octahedral;
};

ir::Props mirror_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  const MirrorP q = view<MirrorP>(n);
  ir::Props p = bound_of(kid, 3);
  for (int i = 0; i < 3; ++i)
    if (q.axes[i] != 0) {
      double hi = std::max(p.bounds.hi[i], 0.0);
      p.bounds.lo[i] = -hi, p.bounds.hi[i] = hi;
    }
  return p;
}

Sample mirror_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  const V3 a = view<MirrorP>(n).axes;
  return child_at(g, n, {a[0] != 0 ? std::fabs(p[0]) : p[0], a[1] != 0 ? std::fabs(p[1]) : p[1],
                         a[2] != 0 ? std::fabs(p[2]) : p[2]});
}

Carried mirror_walk(Walker& w, const ir::Node& n, const std::string& p) {
  const V3 a = view<MirrorP>(n).axes;
  auto axis = [&](int i, const char* c) { return a[i] != 0 ? fmt::format("fabs({}.{})", p, c) : p + "." + c; };
  return w.child(n.children[0], w.point(n, fmt::format("v3({}, {}, {})", axis(0, "x"), axis(1, "y"), axis(2, "z"))));
}

ir::Props symmetry_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  ir::Props p = bound_of(kid, 12);
  need_bounds(n, p.bounds, "symmetry");
  p.bounds = Box3::cube(std::hypot(reach(p.bounds, 0), reach(p.bounds, 1), reach(p.bounds, 2)));
  return p;
}

Sample symmetry_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  V3 v = p;
  if (view<SymmetryP>(n).octahedral != 0) {
    // Octahedral: the chamber x >= y >= z >= 0.
    for (double& c : v) c = std::fabs(c);
    std::sort(v.begin(), v.end(), std::greater<>());
  } else {
    // Tetrahedral: reflect through x = -y, x = -z, y = -z in turn.
    if (v[0] + v[1] < 0) v = {-v[1], -v[0], v[2]};
    if (v[0] + v[2] < 0) v = {-v[2], v[1], -v[0]};
    if (v[1] + v[2] < 0) v = {v[0], -v[2], -v[1]};
  }
  return child_at(g, n, v);
}

Carried symmetry_walk(Walker& w, const ir::Node& n, const std::string& p) {
  std::string fn = view<SymmetryP>(n).octahedral != 0 ? "dm_symmetry_octahedral" : "dm_symmetry_tetrahedral";
  return w.child(n.children[0], w.point(n, fmt::format("{}({})", w.call(fn), p)));
}

}  // namespace

namespace {
constexpr ParamDoc k_mirror_docs[] = {
    {"mirror", "x, y, z or a list of them", "", "", "the axes whose planes mirror"},
};
constexpr ParamDoc k_symmetry_docs[] = {
    {"symmetry", "one of tetrahedral\\|octahedral", "", "", "the group of reflections"},
};
}  // namespace

namespace described {
extern const Description Mirror{.kind = ir::Kind::Mirror,
                                .yaml = "mirror",
                                .example = "{union: [{sphere: {radius: 0.3}, translate: [0.4, 0.3, 0]}], mirror: [x, y]}",
                                .param_count = count_of<MirrorP>(),
                                .child_props = mirror_props,
                                .evaluate = mirror_evaluate,
                                .walk = mirror_walk,
                                .summary = "Folds space across the planes through the origin: the positive half of each axis is mirrored to the negative.",
                                .written_as = "`mirror: AXIS` or `mirror: [AXES]` on any node",
                                .docs = k_mirror_docs};
extern const Description Symmetry{.kind = ir::Kind::Symmetry,
                                  .yaml = "symmetry",
                                  .example = "{union: [{sphere: {radius: 0.2}, translate: [0.5, 0.2, 0.1]}], symmetry: octahedral}",
                                  .param_count = count_of<SymmetryP>(),
                                  .child_props = symmetry_props,
                                  .evaluate = symmetry_evaluate,
                                  .walk = symmetry_walk,
                                  .summary = "Reflects the node across the symmetry planes of a tetrahedron or an octahedron.",
                                  .written_as = "`symmetry: tetrahedral|octahedral` on any bounded node",
                                  .docs = k_symmetry_docs};
}

}  // namespace sdfc::kinds
