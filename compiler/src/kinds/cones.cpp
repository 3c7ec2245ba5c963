// cone, capped_cone, round_cone: solids of revolution about z.
#include <fmt/format.h>

#include "shape_math.hpp"

SDFC_KIND(Cone,            25, "cone",          Primitive, 0, "radius,half_height",                    "sd_cone")
SDFC_KIND(CappedCone,      26, "capped_cone",   Primitive, 0, "half_height,bottom_radius,top_radius",  "sd_capped_cone")
SDFC_KIND(RoundCone,       27, "round_cone",    Primitive, 0, "bottom_radius,top_radius,half_height",  "sd_round_cone")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct ConeP {
  double radius, half_height;
};
struct CappedConeP {
  double half_height, bottom_radius, top_radius;
};
struct RoundConeP {
  double bottom_radius, top_radius, half_height;
};

ir::NodeId lower_cone(Lowering& l) {
  frontend::MapReader m = l.map({"radius", "height"});
  double radius = m.number("radius", 0.5, Range::positive()), height = m.number("height", 1, Range::positive());
  return l.make(ConeP{radius, height / 2});
}

// capped_cone and round_cone read the same keys.
struct Radii {
  double height, r1, r2;
};
Radii read_radii(Lowering& l, frontend::MapReader& m) {
  double height = m.number("height", 1, Range::positive());
  double r1 = m.number("bottom_radius", 0.5, Range::non_negative());
  double r2 = m.number("top_radius", 0.25, Range::non_negative());
  if (r1 == 0 && r2 == 0) l.fail(m, "top_radius", "bottom_radius and top_radius cannot both be 0");
  return {height, r1, r2};
}

ir::NodeId lower_capped_cone(Lowering& l) {
  frontend::MapReader m = l.map({"height", "bottom_radius", "top_radius"});
  Radii r = read_radii(l, m);
  return l.make(CappedConeP{r.height / 2, r.r1, r.r2});
}

ir::NodeId lower_round_cone(Lowering& l) {
  frontend::MapReader m = l.map({"height", "bottom_radius", "top_radius"});
  Radii r = read_radii(l, m);
  // The round cone is the hull of two spheres: one must not swallow the other.
  if (std::fabs(r.r1 - r.r2) >= r.height)
    l.fail(m, "height", fmt::format("round_cone.height: {} must exceed |bottom_radius - top_radius| = {}", r.height,
                                    std::fabs(r.r1 - r.r2)));
  return l.make(RoundConeP{r.r1, r.r2, r.height / 2});
}

ir::Props cone_props(const ir::Node& n) {
  auto c = view<ConeP>(n);
  return leaf(box(-c.radius, -c.radius, -c.half_height, c.radius, c.radius, c.half_height), 30);
}
ir::Props capped_cone_props(const ir::Node& n) {
  auto c = view<CappedConeP>(n);
  double r = std::max(c.bottom_radius, c.top_radius);
  return leaf(box(-r, -r, -c.half_height, r, r, c.half_height), 32);
}
ir::Props round_cone_props(const ir::Node& n) {
  auto c = view<RoundConeP>(n);
  double r = std::max(c.bottom_radius, c.top_radius);
  return leaf(box(-r, -r, -c.half_height - c.bottom_radius, r, r, c.half_height + c.top_radius), 26);
}

double cone_distance(const ir::Node& n, const V3& pa) {
  auto c = view<ConeP>(n);
  double r = c.radius, hh = c.half_height;
  // Profile: apex A = (0, hh), base rim B = (r, -hh), base centre (0, -hh).
  double x = len2(pa[0], pa[1]), y = pa[2];
  double ex = r, ey = -2 * hh;  // apex -> rim
  double t = std::clamp((x * ex + (y - hh) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
  double side = len2(x - ex * t, y - hh - ey * t);
  double base = len2(x - std::min(x, r), y + hh);
  double d = std::min(side, base);
  bool inside = y > -hh && y < hh && x < r * (hh - y) / (2 * hh);
  return inside ? -d : d;
}

double capped_cone_distance(const ir::Node& n, const V3& pa) {
  auto c = view<CappedConeP>(n);
  double h = c.half_height, r1 = c.bottom_radius, r2 = c.top_radius;
  double x = len2(pa[0], pa[1]), y = pa[2];
  // Nearest point on the slanted side (bottom rim to top rim) and on the caps.
  double ex = r2 - r1, ey = 2 * h;
  double t = std::clamp(((x - r1) * ex + (y + h) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
  double side = len2(x - r1 - ex * t, y + h - ey * t);
  double top = len2(x - std::min(x, r2), y - h), bottom = len2(x - std::min(x, r1), y + h);
  double d = std::min({side, top, bottom});
  bool inside = std::fabs(y) < h && x < r1 + (r2 - r1) * (y + h) / (2 * h);
  return inside ? -d : d;
}

double round_cone_distance(const ir::Node& n, const V3& pa) {
  auto c = view<RoundConeP>(n);
  double r1 = c.bottom_radius, r2 = c.top_radius, hh = c.half_height;
  double x = len2(pa[0], pa[1]), y = pa[2] + hh, L = 2 * hh;
  double b = (r1 - r2) / L, a = std::sqrt(1 - b * b);
  double k = -b * x + a * y;
  if (k < 0) return len2(x, y) - r1;
  if (k > a * L) return len2(x, y - L) - r2;
  return x * a + y * b - r1;
}

}  // namespace

namespace described {
extern const Description Cone{ir::Kind::Cone, "cone", "{cone: {radius: 0.6, height: 1.2}}", count_of<ConeP>(),
                              lower_cone, cone_props, "radius, half_height", cone_distance};
extern const Description CappedCone{ir::Kind::CappedCone, "capped_cone",
                                    "{capped_cone: {height: 1.0, bottom_radius: 0.6, top_radius: 0.25}}",
                                    count_of<CappedConeP>(), lower_capped_cone, capped_cone_props,
                                    "half_height, bottom_radius, top_radius", capped_cone_distance};
extern const Description RoundCone{ir::Kind::RoundCone, "round_cone",
                                   "{round_cone: {height: 0.8, bottom_radius: 0.4, top_radius: 0.15}}",
                                   count_of<RoundConeP>(), lower_round_cone, round_cone_props,
                                   "bottom_radius, top_radius, half_height", round_cone_distance};
}  // namespace described

}  // namespace sdfc::kinds
