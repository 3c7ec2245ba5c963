// box: full sizes in the scene, half extents in the node; rounded edges.
#include <fmt/format.h>

#include "sdfc/kinds/params.hpp"
#include "shape_math.hpp"

SDFC_KIND(Box, 1, "box", Primitive, 0, "hx,hy,hz,radius", "sd_box")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct BoxP {
  V3 h;  // half extents
  double radius;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"size", "radius"});
  frontend::Param3 size = m.param3("size", {1, 1, 1}, Range::positive());
  frontend::Param radius = m.param("radius", 0.0, Range::non_negative());
  double smallest = std::min({size[0].lo, size[1].lo, size[2].lo});
  if (radius.hi > 0.5 * smallest && m.get("radius"))
    l.report(m, "radius", fmt::format("box.radius: {} is more than half the smallest side ({})", radius.hi, smallest));
  return l.make_animated({size[0].scaled(0.5), size[1].scaled(0.5), size[2].scaled(0.5), radius});
}

ir::Props props(const ir::Node& n) {
  V3 h = view<BoxP>(n).h;
  return leaf(box(-h[0], -h[1], -h[2], h[0], h[1], h[2]), 16);
}

double distance(const ir::Node& n, const V3& p) {
  auto b = view<BoxP>(n);
  double r = b.radius;
  double dx = std::fabs(p[0]) - b.h[0] + r, dy = std::fabs(p[1]) - b.h[1] + r, dz = std::fabs(p[2]) - b.h[2] + r;
  double outside = len({std::max(dx, 0.0), std::max(dy, 0.0), std::max(dz, 0.0)});
  double inside = std::min(std::max({dx, dy, dz}), 0.0);
  return outside + inside - r;
}

constexpr ParamDoc k_docs[] = {
    {"size", "vec3", "[1, 1, 1]", "each > 0", "the full edge lengths along x, y and z"},
    {"radius", "number", "0", ">= 0, at most half the smallest side", "rounds the edges inside the box (0: sharp)"},
};

}  // namespace

std::array<double, 3> box_half_extent(const ir::Node& box) { return view<BoxP>(box).h; }
double box_edge_radius(const ir::Node& box) { return view<BoxP>(box).radius; }

namespace described {
extern const Description Box{.kind = ir::Kind::Box,
                             .yaml = "box",
                             .example = "{box: {size: [1, 0.8, 0.6], radius: 0.1}}",
                             .param_count = count_of<BoxP>(),
                             .lower = lower,
                             .props = props,
                             .call_args = "h, radius",
                             .distance = distance,
                             .dual_normals = true,
                             .gradient_function = "sdg_box",
                             .summary = "A box centred on the origin, its edges optionally rounded.",
                             .docs = k_docs};
}

}  // namespace sdfc::kinds
