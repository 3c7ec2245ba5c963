#include "catalogue_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sdfc::frontend {

using ir::Kind;
using ir::NodeId;

const std::vector<std::string_view>& catalogue_kinds() {
  static const std::vector<std::string_view> k = {"cone",    "capped_cone", "round_cone", "ellipsoid", "octahedron",
                                                  "hex_prism", "tri_prism", "link",       "rounded_cylinder",
                                                  "pyramid", "segment",     "triangle",   "quad",      "box_frame"};
  return k;
}

namespace {

Vec3d sub(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }

class Catalogue {
 public:
  Catalogue(ValueReader& r, ir::Builder& b, const SourceValue& key, const SourceValue& body)
      : r_(r), b_(b), key_(key), body_(body), at_(key.loc) {}

  std::optional<NodeId> lower() {
    const std::string& k = key_.scalar;
    if (k == "cone") {
      MapReader m = map({"radius", "height"});
      double radius = m.number("radius", 0.5, Range::positive()), height = m.number("height", 1, Range::positive());
      return make(Kind::Cone, {radius, height / 2});
    }
    if (k == "capped_cone" || k == "round_cone") {
      MapReader m = map({"height", "bottom_radius", "top_radius"});
      double height = m.number("height", 1, Range::positive());
      double r1 = m.number("bottom_radius", 0.5, Range::non_negative());
      double r2 = m.number("top_radius", 0.25, Range::non_negative());
      if (r1 == 0 && r2 == 0) fail(m, "top_radius", "bottom_radius and top_radius cannot both be 0");
      if (k == "capped_cone") return make(Kind::CappedCone, {height / 2, r1, r2});
      // The round cone is the hull of two spheres: one must not swallow the other.
      if (std::fabs(r1 - r2) >= height)
        fail(m, "height", fmt::format("round_cone.height: {} must exceed |bottom_radius - top_radius| = {}", height,
                                      std::fabs(r1 - r2)));
      return make(Kind::RoundCone, {r1, r2, height / 2});
    }
    if (k == "ellipsoid") {
      MapReader m = map({"radii"});
      Vec3d r = m.vec3("radii", {1, 0.5, 0.25}, Range::positive());
      return make(Kind::Ellipsoid, {r[0], r[1], r[2]});
    }
    if (k == "octahedron") {
      MapReader m = map({"size"});
      return make(Kind::Octahedron, {m.number("size", 1, Range::positive())});
    }
    if (k == "hex_prism") {
      MapReader m = map({"apothem", "height"});
      double a = m.number("apothem", 0.5, Range::positive()), height = m.number("height", 1, Range::positive());
      return make(Kind::HexPrism, {a, height / 2});
    }
    if (k == "tri_prism") {
      MapReader m = map({"side", "height"});
      double side = m.number("side", 1, Range::positive()), height = m.number("height", 1, Range::positive());
      return make(Kind::TriPrism, {side / 2, height / 2});
    }
    if (k == "link") {
      MapReader m = map({"length", "major_radius", "minor_radius"});
      double length = m.number("length", 0.5, Range::non_negative());
      double major = m.number("major_radius", 0.4, Range::positive());
      double minor = m.number("minor_radius", 0.1, Range::positive());
      if (minor >= major) fail(m, "minor_radius", fmt::format("link.minor_radius: {} must be less than major_radius ({})", minor, major));
      return make(Kind::Link, {length / 2, major, minor});
    }
    if (k == "rounded_cylinder") {
      MapReader m = map({"radius", "height", "edge_radius"});
      double radius = m.number("radius", 0.5, Range::positive()), height = m.number("height", 1, Range::positive());
      double edge = m.number("edge_radius", 0.1, Range::non_negative());
      if (edge > std::min(radius, height / 2))
        fail(m, "edge_radius", fmt::format("rounded_cylinder.edge_radius: {} is more than min(radius, height/2) = {}",
                                           edge, std::min(radius, height / 2)));
      return make(Kind::RoundedCylinder, {radius, height / 2, edge});
    }
    if (k == "pyramid") {
      MapReader m = map({"base", "height"});
      double base = m.number("base", 1, Range::positive()), height = m.number("height", 1, Range::positive());
      return make(Kind::Pyramid, {base, height});
    }
    if (k == "segment") {
      // A segment with a radius is the capsule's shape; it shares its node.
      MapReader m = map({"a", "b", "radius"});
      Vec3d a = m.vec3("a", {0, 0, -0.5}), bb = m.vec3("b", {0, 0, 0.5});
      double radius = m.number("radius", 0.1, Range::positive());
      return make(Kind::Capsule, {a[0], a[1], a[2], bb[0], bb[1], bb[2], radius});
    }
    if (k == "triangle") {
      MapReader m = map({"a", "b", "c", "thickness"});
      Vec3d a = m.vec3("a", {-0.5, -0.5, 0}), bb = m.vec3("b", {0.5, -0.5, 0}), c = m.vec3("c", {0, 0.5, 0});
      double t = m.number("thickness", 0.05, Range::positive());
      if (norm(cross(sub(bb, a), sub(c, a))) < 1e-9)
        fail(m, "c", "triangle: the corners a, b, c lie on one line; they must span a triangle");
      return make(Kind::Triangle, {a[0], a[1], a[2], bb[0], bb[1], bb[2], c[0], c[1], c[2], t / 2});
    }
    if (k == "quad") {
      MapReader m = map({"a", "b", "c", "d", "thickness"});
      Vec3d a = m.vec3("a", {-0.5, -0.5, 0}), bb = m.vec3("b", {0.5, -0.5, 0}), c = m.vec3("c", {0.5, 0.5, 0}),
            d = m.vec3("d", {-0.5, 0.5, 0});
      double t = m.number("thickness", 0.05, Range::positive());
      check_quad(m, {a, bb, c, d});
      return make(Kind::Quad, {a[0], a[1], a[2], bb[0], bb[1], bb[2], c[0], c[1], c[2], d[0], d[1], d[2], t / 2});
    }
    if (k == "box_frame") {
      MapReader m = map({"size", "edge"});
      Vec3d size = m.vec3("size", {1, 1, 1}, Range::positive());
      double edge = m.number("edge", 0.05, Range::positive());
      double smallest = std::min({size[0], size[1], size[2]});
      if (edge >= smallest / 2)
        fail(m, "edge", fmt::format("box_frame.edge: {} must be less than half the smallest side ({})", edge, smallest / 2));
      return make(Kind::BoxFrame, {size[0] / 2, size[1] / 2, size[2] / 2, edge});
    }
    return std::nullopt;
  }

 private:
  MapReader map(std::initializer_list<std::string_view> allowed) { return MapReader(r_, body_, key_.scalar, allowed); }

  NodeId make(Kind k, std::vector<double> params) {
    if (failed_) return ir::kNoNode;
    return b_.make(k, std::move(params), {}, at_);
  }

  void fail(const MapReader& m, std::string_view key, const std::string& msg) {
    const SourceValue* v = m.get(key);
    r_.sink().error(v ? v->loc : body_.loc, msg, "");
    failed_ = true;
  }

  // The quad's formula needs a flat, convex outline a -> b -> c -> d.
  void check_quad(const MapReader& m, const std::array<Vec3d, 4>& q) {
    Vec3d n = cross(sub(q[1], q[0]), sub(q[3], q[0]));
    double size = 0;
    for (int i = 0; i < 4; ++i) size = std::max(size, norm(sub(q[(i + 1) % 4], q[i])));
    if (norm(n) < 1e-9 * size * size) return fail(m, "d", "quad: the corners a, b, d lie on one line");
    Vec3d u = {n[0] / norm(n), n[1] / norm(n), n[2] / norm(n)};
    // Corners written to 4 decimals are up to ~1.5e-4 x size off one plane.
    if (std::fabs(dot(u, sub(q[2], q[0]))) > 5e-4 * size)
      return fail(m, "c", fmt::format("quad: corner c is {:.3g} off the plane of a, b, d; a quad must be flat",
                                      dot(u, sub(q[2], q[0]))));
    for (int i = 0; i < 4; ++i) {
      Vec3d turn = cross(sub(q[(i + 1) % 4], q[i]), sub(q[(i + 2) % 4], q[(i + 1) % 4]));
      if (dot(turn, u) <= 0)
        return fail(m, "d", "quad: the corners a, b, c, d must go round a convex outline in order");
    }
  }

  ValueReader& r_;
  ir::Builder& b_;
  const SourceValue& key_;
  const SourceValue& body_;
  SourceLoc at_;
  bool failed_ = false;
};

}  // namespace

std::optional<NodeId> lower_catalogue(ValueReader& r, ir::Builder& b, const SourceValue& key, const SourceValue& body) {
  return Catalogue(r, b, key, body).lower();
}

}  // namespace sdfc::frontend
