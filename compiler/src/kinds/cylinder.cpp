// cylinder: about z, full height in the scene, half height in the node.
#include "shape_math.hpp"

SDFC_KIND(Cylinder, 4, "cylinder", Primitive, 0, "radius,half_height", "sd_cylinder")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct CylinderP {
  double radius, half_height;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"radius", "height"});
  frontend::Param radius = m.param("radius", 0.5, Range::positive());
  frontend::Param height = m.param("height", 1.0, Range::positive());
  return l.make_animated({radius, height.scaled(0.5)});
}

ir::Props props(const ir::Node& n) {
  auto c = view<CylinderP>(n);
  return leaf(box(-c.radius, -c.radius, -c.half_height, c.radius, c.radius, c.half_height), 12);
}

double distance(const ir::Node& n, const V3& p) {
  auto c = view<CylinderP>(n);
  double dr = std::hypot(p[0], p[1]) - c.radius, dz = std::fabs(p[2]) - c.half_height;
  return std::min(std::max(dr, dz), 0.0) + std::hypot(std::max(dr, 0.0), std::max(dz, 0.0));
}

constexpr ParamDoc k_docs[] = {
    {"radius", "number", "0.5", "> 0", "its radius"},
    {"height", "number", "1", "> 0", "the full height, from z = -height/2 to +height/2"},
};

}  // namespace

namespace described {
extern const Description Cylinder{.kind = ir::Kind::Cylinder,
                                  .yaml = "cylinder",
                                  .example = "{cylinder: {radius: 0.5, height: 1.2}}",
                                  .param_count = count_of<CylinderP>(),
                                  .lower = lower,
                                  .props = props,
                                  .call_args = "radius, half_height",
                                  .distance = distance,
                                  .dual_normals = true,
                                  .gradient_function = "sdg_cylinder",
                                  .summary = "A capped cylinder along z.",
                                  .docs = k_docs};
}

}  // namespace sdfc::kinds
