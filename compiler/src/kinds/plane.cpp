// plane: the half-space below n . p = offset (n normalised by the reader).
#include "shape_math.hpp"

SDFC_KIND(Plane, 3, "plane", Primitive, 0, "nx,ny,nz,offset", "sd_plane")

namespace sdfc::kinds {
namespace {
using namespace math;

struct PlaneP {
  V3 n;
  double offset;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"normal", "offset"});
  frontend::Vec3d n = m.direction("normal", {0, 0, 1});
  return l.make_animated({n[0], n[1], n[2], m.param("offset", 0.0)});
}

ir::Props props(const ir::Node&) { return leaf(ir::Box3::everything(), 5); }

double distance(const ir::Node& n, const V3& p) {
  auto s = view<PlaneP>(n);
  return p[0] * s.n[0] + p[1] * s.n[1] + p[2] * s.n[2] - s.offset;
}

constexpr ParamDoc k_docs[] = {
    {"normal", "vec3", "[0, 0, 1]", "not zero", "points out of the solid; it is normalised; fixed, not an expression of time"},
    {"offset", "number", "0", "", "moves the plane along its normal"},
};

}  // namespace

namespace described {
extern const Description Plane{.kind = ir::Kind::Plane,
                               .yaml = "plane",
                               .example = "{plane: {offset: -0.5}}",
                               .param_count = count_of<PlaneP>(),
                               .lower = lower,
                               .props = props,
                               .call_args = "n, offset",
                               .distance = distance,
                               .dual_normals = true,
                               .gradient_function = "sdg_plane",
                               .summary = "The solid half-space below the plane dot(p, normal) = offset.",
                               .docs = k_docs};
}

}  // namespace sdfc::kinds
