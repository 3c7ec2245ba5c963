// triangle, quad: flat polygons thickened into slabs.
#include <fmt/format.h>

#include "shape_math.hpp"

SDFC_KIND(Triangle, 35, "triangle", Primitive, 0, "ax,ay,az,bx,by,bz,cx,cy,cz,half_thickness",          "sd_triangle")
SDFC_KIND(Quad,     36, "quad",     Primitive, 0, "ax,ay,az,bx,by,bz,cx,cy,cz,dx,dy,dz,half_thickness", "sd_quad")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;
using frontend::Vec3d;

struct TriangleP {
  V3 a, b, c;
  double half_thickness;
};
struct QuadP {
  V3 a, b, c, d;
  double half_thickness;
};

Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3d cross3(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3d& a) { return std::sqrt(dot3(a, a)); }

// The corners as they are (they stay fixed: their checks need them), then
// the thickness, which may be an expression of time.
ir::NodeId make_slab(Lowering& l, std::initializer_list<Vec3d> corners, const frontend::Param& thickness) {
  std::vector<frontend::Param> params;
  for (const Vec3d& c : corners) params.insert(params.end(), {c[0], c[1], c[2]});
  params.push_back(thickness.scaled(0.5));
  return l.make_animated(params);
}

ir::NodeId lower_triangle(Lowering& l) {
  frontend::MapReader m = l.map({"a", "b", "c", "thickness"});
  Vec3d a = m.vec3("a", {-0.5, -0.5, 0}), bb = m.vec3("b", {0.5, -0.5, 0}), c = m.vec3("c", {0, 0.5, 0});
  frontend::Param t = m.param("thickness", 0.05, Range::positive());
  if (norm(cross3(sub(bb, a), sub(c, a))) < 1e-9)
    l.fail(m, "c", "triangle: the corners a, b, c lie on one line; they must span a triangle");
  return make_slab(l, {a, bb, c}, t);
}

// The quad's formula needs a flat, convex outline a -> b -> c -> d.
void check_quad(Lowering& l, const frontend::MapReader& m, const std::array<Vec3d, 4>& q) {
  Vec3d n = cross3(sub(q[1], q[0]), sub(q[3], q[0]));
  double size = 0;
  for (int i = 0; i < 4; ++i) size = std::max(size, norm(sub(q[(i + 1) % 4], q[i])));
  if (norm(n) < 1e-9 * size * size) return l.fail(m, "d", "quad: the corners a, b, d lie on one line");
  Vec3d u = {n[0] / norm(n), n[1] / norm(n), n[2] / norm(n)};
  // Corners written to 4 decimals are up to ~1.5e-4 x size off one plane.
  if (std::fabs(dot3(u, sub(q[2], q[0]))) > 5e-4 * size)
    return l.fail(m, "c", fmt::format("quad: corner c is {:.3g} off the plane of a, b, d; a quad must be flat",
                                      dot3(u, sub(q[2], q[0]))));
  for (int i = 0; i < 4; ++i) {
    Vec3d turn = cross3(sub(q[(i + 1) % 4], q[i]), sub(q[(i + 2) % 4], q[(i + 1) % 4]));
    if (dot3(turn, u) <= 0) return l.fail(m, "d", "quad: the corners a, b, c, d must go round a convex outline in order");
  }
}

ir::NodeId lower_quad(Lowering& l) {
  frontend::MapReader m = l.map({"a", "b", "c", "d", "thickness"});
  Vec3d a = m.vec3("a", {-0.5, -0.5, 0}), bb = m.vec3("b", {0.5, -0.5, 0}), c = m.vec3("c", {0.5, 0.5, 0}),
        d = m.vec3("d", {-0.5, 0.5, 0});
  frontend::Param t = m.param("thickness", 0.05, Range::positive());
  check_quad(l, m, {a, bb, c, d});
  return make_slab(l, {a, bb, c, d}, t);
}

// The box around a set of corners, grown by the slab's half thickness.
ir::Box3 hull(std::initializer_list<V3> corners, double pad) {
  ir::Box3 b{{ir::Box3::inf(), ir::Box3::inf(), ir::Box3::inf()}, {-ir::Box3::inf(), -ir::Box3::inf(), -ir::Box3::inf()}};
  for (const V3& c : corners)
    for (int i = 0; i < 3; ++i) b.lo[i] = std::min(b.lo[i], c[i]), b.hi[i] = std::max(b.hi[i], c[i]);
  return b.padded(pad);
}

ir::Props triangle_props(const ir::Node& n) {
  auto t = view<TriangleP>(n);
  return leaf(hull({t.a, t.b, t.c}, t.half_thickness), 70);
}
ir::Props quad_props(const ir::Node& n) {
  auto q = view<QuadP>(n);
  return leaf(hull({q.a, q.b, q.c, q.d}, q.half_thickness), 95);
}

// Unsigned distance to a planar convex polygon: to its plane when the
// projection falls inside every edge, else to the nearest edge.
double polygon(V p, const V* c, int n) {
  V nor = cross(c[1] - c[0], c[n - 1] - c[0]);
  bool inside = true;
  double edges = 1e300;
  for (int i = 0; i < n; ++i) {
    V a = c[i], b = c[(i + 1) % n];
    if (dot(cross(b - a, nor), p - a) > 0) inside = false;
    edges = std::min(edges, seg2(p, a, b));
  }
  if (inside) return std::fabs(dot(nor, p - c[0])) / len(nor);
  return std::sqrt(edges);
}

double triangle_distance(const ir::Node& n, const V3& p) {
  auto t = view<TriangleP>(n);
  V c[3] = {at(t.a), at(t.b), at(t.c)};
  return polygon(at(p), c, 3) - t.half_thickness;
}
double quad_distance(const ir::Node& n, const V3& p) {
  auto q = view<QuadP>(n);
  V c[4] = {at(q.a), at(q.b), at(q.c), at(q.d)};
  return polygon(at(p), c, 4) - q.half_thickness;
}

constexpr ParamDoc k_triangle_docs[] = {
    {"a", "vec3", "[-0.5, -0.5, 0]", "", "a corner; the corners are fixed, not expressions of time"},
    {"b", "vec3", "[0.5, -0.5, 0]", "", "a corner"},
    {"c", "vec3", "[0, 0.5, 0]", "not on the line through a and b", "a corner"},
    {"thickness", "number", "0.05", "> 0", "the full thickness of the slab"},
};
constexpr ParamDoc k_quad_docs[] = {
    {"a", "vec3", "[-0.5, -0.5, 0]", "", "the corners, in order round the outline; fixed, not expressions of time"},
    {"b", "vec3", "[0.5, -0.5, 0]", "", "the next corner"},
    {"c", "vec3", "[0.5, 0.5, 0]", "in the plane of a, b and d", "the next corner"},
    {"d", "vec3", "[-0.5, 0.5, 0]", "a, b, c, d convex", "the last corner"},
    {"thickness", "number", "0.05", "> 0", "the full thickness of the slab"},
};

}  // namespace

namespace described {
extern const Description Triangle{
    .kind = ir::Kind::Triangle,
    .yaml = "triangle",
    .example = "{triangle: {a: [-0.5, -0.4, -0.1], b: [0.6, -0.3, 0.2], c: [0.0, 0.5, 0.0], thickness: 0.08}}",
    .param_count = count_of<TriangleP>(),
    .lower = lower_triangle,
    .props = triangle_props,
    .call_args = "a, b, c, half_thickness",
    .distance = triangle_distance,
    .summary = "A thin slab around a triangle.",
    .docs = k_triangle_docs};
extern const Description Quad{.kind = ir::Kind::Quad,
                              .yaml = "quad",
                              .example =
                                  "{quad: {a: [-0.5, -0.5, 0], b: [0.6, -0.4, 0], c: [0.5, 0.5, 0], d: [-0.4, 0.4, 0], "
                                  "thickness: 0.08}, rotate: [20, 30, 0]}",
                              .param_count = count_of<QuadP>(),
                              .lower = lower_quad,
                              .props = quad_props,
                              .call_args = "a, b, c, d, half_thickness",
                              .distance = quad_distance,
                              .summary = "A thin slab around a flat, convex quadrilateral.",
                              .docs = k_quad_docs};
}  // namespace described

}  // namespace sdfc::kinds
