// capsule: the points within `radius` of the segment a-b.
#include "shape_math.hpp"

SDFC_KIND(Capsule, 5, "capsule", Primitive, 0, "ax,ay,az,bx,by,bz,radius", "sd_capsule")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct CapsuleP {
  V3 a, b;
  double radius;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"a", "b", "radius"});
  frontend::Param3 a = m.param3("a", {0, 0, -0.5}), bb = m.param3("b", {0, 0, 0.5});
  frontend::Param radius = m.param("radius", 0.25, Range::positive());
  return l.make_animated({a[0], a[1], a[2], bb[0], bb[1], bb[2], radius});
}

ir::Props props(const ir::Node& n) {
  auto c = view<CapsuleP>(n);
  double r = c.radius;
  return leaf(box(std::min(c.a[0], c.b[0]) - r, std::min(c.a[1], c.b[1]) - r, std::min(c.a[2], c.b[2]) - r,
                  std::max(c.a[0], c.b[0]) + r, std::max(c.a[1], c.b[1]) + r, std::max(c.a[2], c.b[2]) + r),
              18);
}

double distance(const ir::Node& n, const V3& p) {
  auto c = view<CapsuleP>(n);
  double pa[3] = {p[0] - c.a[0], p[1] - c.a[1], p[2] - c.a[2]};
  double ba[3] = {c.b[0] - c.a[0], c.b[1] - c.a[1], c.b[2] - c.a[2]};
  double bb = ba[0] * ba[0] + ba[1] * ba[1] + ba[2] * ba[2];
  double h = bb > 0 ? std::clamp((pa[0] * ba[0] + pa[1] * ba[1] + pa[2] * ba[2]) / bb, 0.0, 1.0) : 0.0;
  return len({pa[0] - ba[0] * h, pa[1] - ba[1] * h, pa[2] - ba[2] * h}) - c.radius;
}

constexpr ParamDoc k_docs[] = {
    {"a", "vec3", "[0, 0, -0.5]", "", "one end of the segment"},
    {"b", "vec3", "[0, 0, 0.5]", "", "the other end"},
    {"radius", "number", "0.25", "> 0", "the distance from the segment"},
};

}  // namespace

namespace described {
extern const Description Capsule{
    .kind = ir::Kind::Capsule,
    .yaml = "capsule",
    .example = "{capsule: {a: [-0.4, 0.1, -0.3], b: [0.3, -0.2, 0.4], radius: 0.15}}",
    .param_count = count_of<CapsuleP>(),
    .lower = lower,
    .props = props,
    .call_args = "a, b, radius",
    .distance = distance,
    .dual_normals = true,
    .gradient_function = "sdg_capsule",
    .summary = "All points within radius of the segment from a to b (`segment` is another name for it).",
    .docs = k_docs};
}

}  // namespace sdfc::kinds
