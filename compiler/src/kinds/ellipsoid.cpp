// ellipsoid: radii along x, y, z. No closed form: a bound (Quilez).
#include "shape_math.hpp"

SDFC_KIND(Ellipsoid, 28, "ellipsoid", Primitive, 0, "rx,ry,rz", "sd_ellipsoid")

namespace sdfc::kinds {
namespace {
using namespace math;

struct EllipsoidP {
  V3 r;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"radii"});
  frontend::Param3 r = m.param3("radii", {1, 0.5, 0.25}, frontend::Range::positive());
  return l.make_animated({r[0], r[1], r[2]});
}

ir::Props props(const ir::Node& n) {
  V3 r = view<EllipsoidP>(n).r;
  return leaf(box(-r[0], -r[1], -r[2], r[0], r[1], r[2]), 20, ir::DistanceClass::Bound);
}

double distance(const ir::Node& n, const V3& pa) {
  V3 r = view<EllipsoidP>(n).r;
  V p = at(pa);
  double k0 = len({p.x / r[0], p.y / r[1], p.z / r[2]});
  double k1 = len({p.x / (r[0] * r[0]), p.y / (r[1] * r[1]), p.z / (r[2] * r[2])});
  double rmin = std::min({r[0], r[1], r[2]});
  return std::max(k1 > 0 ? k0 * (k0 - 1) / k1 : 0.0, (k0 - 1) * rmin);
}

constexpr ParamDoc k_docs[] = {
    {"radii", "vec3", "[1, 0.5, 0.25]", "each > 0", "the semi-axes along x, y and z"},
};

}  // namespace

namespace described {
extern const Description Ellipsoid{
    .kind = ir::Kind::Ellipsoid,
    .yaml = "ellipsoid",
    .example = "{ellipsoid: {radii: [0.8, 0.5, 0.3]}}",
    .param_count = count_of<EllipsoidP>(),
    .lower = lower,
    .props = props,
    .call_args = "r",
    .distance = distance,
    .summary = "An ellipsoid centred on the origin; its distance is a bound, as no closed form exists.",
    .docs = k_docs};
}

}  // namespace sdfc::kinds
