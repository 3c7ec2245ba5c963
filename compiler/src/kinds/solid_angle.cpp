// solid_angle: the part of a ball inside a cone about +z with its apex at
// the centre (Quilez's sdSolidAngle, z up). Exact.
#include <numbers>

#include "shape_math.hpp"

SDFC_KIND(SolidAngle, 54, "solid_angle", Primitive, 0, "sin_angle,cos_angle,radius", "sd_solid_angle")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct SolidAngleP {
  double sin_angle, cos_angle, radius;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"angle", "radius"});
  // The cone's half-angle in degrees: 180 is the whole ball.
  // The angle stays fixed (the node holds its sine and cosine); the radius may move.
  double angle = m.number("angle", 30, Range::positive(180));
  frontend::Param radius = m.param("radius", 1, Range::positive());
  double a = angle * std::numbers::pi / 180;
  return l.make_animated({std::sin(a), std::cos(a), radius});
}

ir::Props props(const ir::Node& n) {
  auto s = view<SolidAngleP>(n);
  // Past 90 degrees the ball's equator is inside: the full radius across.
  double across = s.cos_angle < 0 ? s.radius : s.radius * s.sin_angle;
  double below = std::min(0.0, s.radius * s.cos_angle);
  return leaf(box(-across, -across, below, across, across, s.radius), 22);
}

double distance(const ir::Node& n, const V3& p) {
  auto s = view<SolidAngleP>(n);
  double qx = len2(p[0], p[1]), qy = p[2];
  double l = len2(qx, qy) - s.radius;
  double t = std::clamp(qx * s.sin_angle + qy * s.cos_angle, 0.0, s.radius);
  double m = len2(qx - s.sin_angle * t, qy - s.cos_angle * t);
  return std::max(l, m * sgn(s.cos_angle * qx - s.sin_angle * qy));
}

constexpr ParamDoc k_docs[] = {
    {"angle", "number", "30", "> 0, at most 180", "the cone's half-angle in degrees (180: the whole ball); fixed, not an expression of time"},
    {"radius", "number", "1", "> 0", "the radius of the ball"},
};

}  // namespace

namespace described {
extern const Description SolidAngle{.kind = ir::Kind::SolidAngle,
                                    .yaml = "solid_angle",
                                    .example = "{solid_angle: {angle: 40, radius: 0.8}}",
                                    .param_count = count_of<SolidAngleP>(),
                                    .lower = lower,
                                    .props = props,
                                    .call_args = "sin_angle, cos_angle, radius",
                                    .distance = distance,
                                    .summary = "The part of a ball inside a cone about +z with its apex at the centre.",
                                    .docs = k_docs};
}

}  // namespace sdfc::kinds
