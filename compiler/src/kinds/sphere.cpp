// sphere: centred at the origin.
#include "sdfc/kinds/params.hpp"
#include "shape_math.hpp"

SDFC_KIND(Sphere, 0, "sphere", Primitive, 0, "radius", "sd_sphere")

namespace sdfc::kinds {
namespace {
using namespace math;

struct SphereP {
  double radius;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"radius"});
  return l.make_animated({m.param("radius", 1.0, frontend::Range::positive())});
}

ir::Props props(const ir::Node& n) { return leaf(ir::Box3::cube(view<SphereP>(n).radius), 6); }

double distance(const ir::Node& n, const V3& p) {
  return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - view<SphereP>(n).radius;
}

constexpr ParamDoc k_docs[] = {
    {"radius", "number", "1", "> 0", "its radius"},
};

}  // namespace

double sphere_radius(const ir::Node& sphere) { return view<SphereP>(sphere).radius; }

namespace described {
extern const Description Sphere{.kind = ir::Kind::Sphere,
                                .yaml = "sphere",
                                .example = "{sphere: {radius: 0.7}}",
                                .param_count = count_of<SphereP>(),
                                .lower = lower,
                                .props = props,
                                .call_args = "radius",
                                .distance = distance,
                                .dual_normals = true,
                                .gradient_function = "sdg_sphere",
                                .summary = "A ball centred on the origin.",
                                .docs = k_docs};
}

}  // namespace sdfc::kinds
