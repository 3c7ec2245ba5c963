// rounded_cylinder: a cylinder about z with rounded rims.
#include <fmt/format.h>

#include "shape_math.hpp"

SDFC_KIND(RoundedCylinder, 33, "rounded_cylinder", Primitive, 0, "radius,half_height,edge_radius", "sd_rounded_cylinder")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct RoundedCylinderP {
  double radius, half_height, edge_radius;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"radius", "height", "edge_radius"});
  frontend::Param radius = m.param("radius", 0.5, Range::positive()), height = m.param("height", 1, Range::positive());
  frontend::Param edge = m.param("edge_radius", 0.1, Range::non_negative());
  // At every time: the largest edge against the smallest radius and height.
  double room = std::min(radius.lo, height.lo / 2);
  if (edge.hi > room)
    l.fail(m, "edge_radius",
           fmt::format("rounded_cylinder.edge_radius: {} is more than min(radius, height/2) = {}", edge.hi, room));
  return l.make_animated({radius, height.scaled(0.5), edge});
}

ir::Props props(const ir::Node& n) {
  auto c = view<RoundedCylinderP>(n);
  return leaf(box(-c.radius, -c.radius, -c.half_height, c.radius, c.radius, c.half_height), 16);
}

double distance(const ir::Node& n, const V3& p) {
  auto c = view<RoundedCylinderP>(n);
  return extrude(len2(p[0], p[1]) - c.radius + c.edge_radius, p[2], c.half_height - c.edge_radius) - c.edge_radius;
}

constexpr ParamDoc k_docs[] = {
    {"radius", "number", "0.5", "> 0", "the outer radius"},
    {"height", "number", "1", "> 0", "the outer height"},
    {"edge_radius", "number", "0.1", ">= 0, at most min(radius, height/2)", "rounds the rims"},
};

}  // namespace

namespace described {
extern const Description RoundedCylinder{
    .kind = ir::Kind::RoundedCylinder,
    .yaml = "rounded_cylinder",
    .example = "{rounded_cylinder: {radius: 0.5, height: 0.9, edge_radius: 0.15}}",
    .param_count = count_of<RoundedCylinderP>(),
    .lower = lower,
    .props = props,
    .call_args = "radius, half_height, edge_radius",
    .distance = distance,
    .summary = "A cylinder along z with rounded rims; its outer radius and height are as given.",
    .docs = k_docs};
}

}  // namespace sdfc::kinds
