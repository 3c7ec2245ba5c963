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
  frontend::Param radius = m.param("radius", 0.5, Range::positive()), height = m.param("height", 1, Range::positive());
  return l.make_animated({radius, height.scaled(0.5)});
}

// capped_cone and round_cone read the same keys.
struct Radii {
  frontend::Param height, r1, r2;
};
Radii read_radii(Lowering& l, frontend::MapReader& m) {
  frontend::Param height = m.param("height", 1, Range::positive());
  frontend::Param r1 = m.param("bottom_radius", 0.5, Range::non_negative());
  frontend::Param r2 = m.param("top_radius", 0.25, Range::non_negative());
  // Both may be 0 at once unless one stays above 0 at every time.
  if (r1.lo == 0 && r2.lo == 0) l.fail(m, "top_radius", "bottom_radius and top_radius cannot both be 0");
  return {height, r1, r2};
}

ir::NodeId lower_capped_cone(Lowering& l) {
  frontend::MapReader m = l.map({"height", "bottom_radius", "top_radius"});
  Radii r = read_radii(l, m);
  return l.make_animated({r.height.scaled(0.5), r.r1, r.r2});
}

ir::NodeId lower_round_cone(Lowering& l) {
  frontend::MapReader m = l.map({"height", "bottom_radius", "top_radius"});
  Radii r = read_radii(l, m);
  // The round cone is the hull of two spheres: one must not swallow the other.
  // At every time: the largest difference of the radii against the smallest height.
  double apart = std::max(r.r1.hi - r.r2.lo, r.r2.hi - r.r1.lo);
  if (apart >= r.height.lo)
    l.fail(m, "height",
           fmt::format("round_cone.height: {} must exceed |bottom_radius - top_radius| = {}", r.height.lo, apart));
  return l.make_animated({r.r1, r.r2, r.height.scaled(0.5)});
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

constexpr ParamDoc k_cone_docs[] = {
    {"radius", "number", "0.5", "> 0", "the radius of the base disc"},
    {"height", "number", "1", "> 0", "base at z = -height/2, apex at +height/2"},
};
constexpr ParamDoc k_capped_cone_docs[] = {
    {"height", "number", "1", "> 0", "from z = -height/2 to +height/2"},
    {"bottom_radius", "number", "0.5", ">= 0, not both radii 0", "the radius at the bottom"},
    {"top_radius", "number", "0.25", ">= 0, not both radii 0", "the radius at the top"},
};
constexpr ParamDoc k_round_cone_docs[] = {
    {"height", "number", "1", "> 0, more than |bottom_radius - top_radius|", "the distance between the centres"},
    {"bottom_radius", "number", "0.5", ">= 0, not both radii 0", "the lower sphere"},
    {"top_radius", "number", "0.25", ">= 0, not both radii 0", "the upper sphere"},
};

}  // namespace

namespace described {
extern const Description Cone{.kind = ir::Kind::Cone,
                              .yaml = "cone",
                              .example = "{cone: {radius: 0.6, height: 1.2}}",
                              .param_count = count_of<ConeP>(),
                              .lower = lower_cone,
                              .props = cone_props,
                              .call_args = "radius, half_height",
                              .distance = cone_distance,
                              .summary = "A cone along z, its base disc down.",
                              .docs = k_cone_docs};
extern const Description CappedCone{.kind = ir::Kind::CappedCone,
                                    .yaml = "capped_cone",
                                    .example = "{capped_cone: {height: 1.0, bottom_radius: 0.6, top_radius: 0.25}}",
                                    .param_count = count_of<CappedConeP>(),
                                    .lower = lower_capped_cone,
                                    .props = capped_cone_props,
                                    .call_args = "half_height, bottom_radius, top_radius",
                                    .distance = capped_cone_distance,
                                    .summary = "A frustum along z; one of its radii may be 0.",
                                    .docs = k_capped_cone_docs};
extern const Description RoundCone{.kind = ir::Kind::RoundCone,
                                   .yaml = "round_cone",
                                   .example = "{round_cone: {height: 0.8, bottom_radius: 0.4, top_radius: 0.15}}",
                                   .param_count = count_of<RoundConeP>(),
                                   .lower = lower_round_cone,
                                   .props = round_cone_props,
                                   .call_args = "bottom_radius, top_radius, half_height",
                                   .distance = round_cone_distance,
                                   .summary = "The hull of two spheres on the z axis, at z = -height/2 and +height/2.",
                                   .docs = k_round_cone_docs};
}  // namespace described

}  // namespace sdfc::kinds
