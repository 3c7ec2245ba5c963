// torus: a ring about z.
#include "shape_math.hpp"

SDFC_KIND(Torus, 2, "torus", Primitive, 0, "major,minor", "sd_torus")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct TorusP {
  double major, minor;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"major_radius", "minor_radius"});
  frontend::Param major = m.param("major_radius", 1.0, Range::positive());
  frontend::Param minor = m.param("minor_radius", 0.25, Range::positive());
  return l.make_animated({major, minor});
}

ir::Props props(const ir::Node& n) {
  auto t = view<TorusP>(n);
  double r = t.major + t.minor;
  return leaf(box(-r, -r, -t.minor, r, r, t.minor), 10);
}

double distance(const ir::Node& n, const V3& p) {
  auto t = view<TorusP>(n);
  double ring = std::hypot(p[0], p[1]) - t.major;
  return std::hypot(ring, p[2]) - t.minor;
}

constexpr ParamDoc k_docs[] = {
    {"major_radius", "number", "1", "> 0", "from the centre to the middle of the tube"},
    {"minor_radius", "number", "0.25", "> 0", "the radius of the tube"},
};

}  // namespace

namespace described {
extern const Description Torus{.kind = ir::Kind::Torus,
                               .yaml = "torus",
                               .example = "{torus: {major_radius: 0.6, minor_radius: 0.2}}",
                               .param_count = count_of<TorusP>(),
                               .lower = lower,
                               .props = props,
                               .call_args = "major, minor",
                               .distance = distance,
                               .dual_normals = true,
                               .gradient_function = "sdg_torus",
                               .summary = "A ring in the xy-plane around the z axis.",
                               .docs = k_docs};
}

}  // namespace sdfc::kinds
