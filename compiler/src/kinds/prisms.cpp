// hex_prism, tri_prism: regular polygons extruded along z.
#include "shape_math.hpp"

SDFC_KIND(HexPrism, 30, "hex_prism", Primitive, 0, "apothem,half_height",   "sd_hex_prism")
SDFC_KIND(TriPrism, 31, "tri_prism", Primitive, 0, "half_side,half_height", "sd_tri_prism")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct HexPrismP {
  double apothem, half_height;
};
struct TriPrismP {
  double half_side, half_height;
};

ir::NodeId lower_hex(Lowering& l) {
  frontend::MapReader m = l.map({"apothem", "height"});
  frontend::Param a = m.param("apothem", 0.5, Range::positive()), height = m.param("height", 1, Range::positive());
  return l.make_animated({a, height.scaled(0.5)});
}
ir::NodeId lower_tri(Lowering& l) {
  frontend::MapReader m = l.map({"side", "height"});
  frontend::Param side = m.param("side", 1, Range::positive()), height = m.param("height", 1, Range::positive());
  return l.make_animated({side.scaled(0.5), height.scaled(0.5)});
}

ir::Props hex_props(const ir::Node& n) {
  auto h = view<HexPrismP>(n);
  double c = h.apothem * 2 / std::sqrt(3.0);  // circumradius
  return leaf(box(-c, -c, -h.half_height, c, c, h.half_height), 26);
}
ir::Props tri_props(const ir::Node& n) {
  auto t = view<TriPrismP>(n);
  double c = t.half_side * 2 / std::sqrt(3.0);
  return leaf(box(-t.half_side, -c, -t.half_height, t.half_side, c, t.half_height), 24);
}

// Signed 2D distance to a convex polygon with counter-clockwise corners c.
double convex2(double x, double y, const V* c, int n) {
  double e2 = 1e300;
  for (int i = 0; i < n; ++i) e2 = std::min(e2, seg2({x, y, 0}, c[i], c[(i + 1) % n]));
  double d = std::sqrt(e2);
  for (int i = 0; i < n; ++i) {
    V e = c[(i + 1) % n] - c[i];
    if (e.x * (y - c[i].y) - e.y * (x - c[i].x) < 0) return d;  // right of an edge: outside
  }
  return -d;
}

// Regular hexagon with flat sides at y = +-a: corners every 60 degrees.
double hexagon(double x, double y, double a) {
  V c[6];
  double r = 2 * a / std::sqrt(3.0);
  for (int i = 0; i < 6; ++i) c[i] = {r * std::cos(i * M_PI / 3), r * std::sin(i * M_PI / 3), 0};
  return convex2(x, y, c, 6);
}

// Equilateral triangle (+-r, -r/sqrt3), (0, 2r/sqrt3).
double triangle2(double x, double y, double r) {
  const double s3 = std::sqrt(3.0);
  V c[3] = {{-r, -r / s3, 0}, {r, -r / s3, 0}, {0, 2 * r / s3, 0}};
  return convex2(x, y, c, 3);
}

double hex_distance(const ir::Node& n, const V3& p) {
  auto h = view<HexPrismP>(n);
  return extrude(hexagon(p[0], p[1], h.apothem), p[2], h.half_height);
}
double tri_distance(const ir::Node& n, const V3& p) {
  auto t = view<TriPrismP>(n);
  return extrude(triangle2(p[0], p[1], t.half_side), p[2], t.half_height);
}

constexpr ParamDoc k_hex_docs[] = {
    {"apothem", "number", "0.5", "> 0", "flat sides at y = +-apothem"},
    {"height", "number", "1", "> 0", "the full height along z"},
};
constexpr ParamDoc k_tri_docs[] = {
    {"side", "number", "1", "> 0", "the side of the triangle"},
    {"height", "number", "1", "> 0", "the full height along z"},
};

}  // namespace

namespace described {
extern const Description HexPrism{.kind = ir::Kind::HexPrism,
                                  .yaml = "hex_prism",
                                  .example = "{hex_prism: {apothem: 0.5, height: 0.8}}",
                                  .param_count = count_of<HexPrismP>(),
                                  .lower = lower_hex,
                                  .props = hex_props,
                                  .call_args = "apothem, half_height",
                                  .distance = hex_distance,
                                  .summary = "A hexagonal prism along z.",
                                  .docs = k_hex_docs};
extern const Description TriPrism{.kind = ir::Kind::TriPrism,
                                  .yaml = "tri_prism",
                                  .example = "{tri_prism: {side: 1.0, height: 0.6}}",
                                  .param_count = count_of<TriPrismP>(),
                                  .lower = lower_tri,
                                  .props = tri_props,
                                  .call_args = "half_side, half_height",
                                  .distance = tri_distance,
                                  .summary = "An equilateral triangle (apex towards +y) extruded along z.",
                                  .docs = k_tri_docs};
}  // namespace described

}  // namespace sdfc::kinds
