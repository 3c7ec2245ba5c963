// box_frame: the twelve edges of a box, as square bars.
#include <fmt/format.h>

#include "shape_math.hpp"

SDFC_KIND(BoxFrame, 37, "box_frame", Primitive, 0, "hx,hy,hz,edge", "sd_box_frame")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct BoxFrameP {
  V3 h;  // half extents
  double edge;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"size", "edge"});
  frontend::Param3 size = m.param3("size", {1, 1, 1}, Range::positive());
  frontend::Param edge = m.param("edge", 0.05, Range::positive());
  // At every time: the largest edge against the smallest side.
  double smallest = std::min({size[0].lo, size[1].lo, size[2].lo});
  if (edge.hi >= smallest / 2)
    l.fail(m, "edge",
           fmt::format("box_frame.edge: {} must be less than half the smallest side ({})", edge.hi, smallest / 2));
  return l.make_animated({size[0].scaled(0.5), size[1].scaled(0.5), size[2].scaled(0.5), edge});
}

ir::Props props(const ir::Node& n) {
  V3 h = view<BoxFrameP>(n).h;
  return leaf(box(-h[0], -h[1], -h[2], h[0], h[1], h[2]), 45);
}

double distance(const ir::Node& n, const V3& pa) {
  auto f = view<BoxFrameP>(n);
  V b = at(f.h);
  double e = f.edge;
  V p = {std::fabs(pa[0]) - b.x, std::fabs(pa[1]) - b.y, std::fabs(pa[2]) - b.z};
  V q = {std::fabs(p.x + e) - e, std::fabs(p.y + e) - e, std::fabs(p.z + e) - e};
  auto bar = [](double x, double y, double z) {
    return len({std::max(x, 0.0), std::max(y, 0.0), std::max(z, 0.0)}) + std::min(std::max({x, y, z}), 0.0);
  };
  return std::min({bar(p.x, q.y, q.z), bar(q.x, p.y, q.z), bar(q.x, q.y, p.z)});
}

constexpr ParamDoc k_docs[] = {
    {"size", "vec3", "[1, 1, 1]", "each > 0", "the full edge lengths along x, y and z"},
    {"edge", "number", "0.05", "> 0, less than half the smallest side", "the side of the bars"},
};

}  // namespace

namespace described {
extern const Description BoxFrame{.kind = ir::Kind::BoxFrame,
                                  .yaml = "box_frame",
                                  .example = "{box_frame: {size: [1.0, 0.8, 0.6], edge: 0.08}}",
                                  .param_count = count_of<BoxFrameP>(),
                                  .lower = lower,
                                  .props = props,
                                  .call_args = "h, edge",
                                  .distance = distance,
                                  .summary = "The twelve edges of a box as square bars.",
                                  .docs = k_docs};
}

}  // namespace sdfc::kinds
