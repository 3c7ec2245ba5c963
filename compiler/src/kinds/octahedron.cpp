// octahedron: |x| + |y| + |z| = size.
#include "shape_math.hpp"

SDFC_KIND(Octahedron, 29, "octahedron", Primitive, 0, "size", "sd_octahedron")

namespace sdfc::kinds {
namespace {
using namespace math;

struct OctahedronP {
  double size;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"size"});
  return l.make_animated({m.param("size", 1, frontend::Range::positive())});
}

ir::Props props(const ir::Node& n) { return leaf(ir::Box3::cube(view<OctahedronP>(n).size), 28); }

double distance(const ir::Node& n, const V3& pa) {
  double s = view<OctahedronP>(n).size;
  V p = {std::fabs(pa[0]), std::fabs(pa[1]), std::fabs(pa[2])};
  double m = p.x + p.y + p.z - s;
  V q;
  if (3 * p.x < m) q = p;
  else if (3 * p.y < m) q = {p.y, p.z, p.x};
  else if (3 * p.z < m) q = {p.z, p.x, p.y};
  else return m / std::sqrt(3.0);
  double k = std::clamp(0.5 * (q.z - q.y + s), 0.0, s);
  return len({q.x, q.y - s + k, q.z - k});
}

constexpr ParamDoc k_docs[] = {
    {"size", "number", "1", "> 0", "its vertices lie at this distance on the axes"},
};

}  // namespace

namespace described {
extern const Description Octahedron{.kind = ir::Kind::Octahedron,
                                    .yaml = "octahedron",
                                    .example = "{octahedron: {size: 0.7}}",
                                    .param_count = count_of<OctahedronP>(),
                                    .lower = lower,
                                    .props = props,
                                    .call_args = "size",
                                    .distance = distance,
                                    .summary = "A regular octahedron centred on the origin.",
                                    .docs = k_docs};
}

}  // namespace sdfc::kinds
