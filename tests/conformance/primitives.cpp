#include "primitives.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sdfc::conformance {

using test::add;
using test::cross;
using test::dot;
using test::mul;
using test::norm;
using test::normalize;
using test::sub;

namespace {

constexpr double kPi = std::numbers::pi;

// Samples a parametric patch f(u, v), u, v in [0, 1] (ends included), with
// about `spacing` between neighbours given the patch's extent along u and v,
// and widens `covering` to half the longest cell diagonal.
template <typename F>
void patch(SurfaceSamples& s, double spacing, double len_u, double len_v, F f) {
  int nu = std::max(1, int(std::ceil(len_u / spacing)));
  int nv = std::max(1, int(std::ceil(len_v / spacing)));
  std::vector<V3> grid;
  grid.reserve(size_t(nu + 1) * (nv + 1));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) grid.push_back(f(double(i) / nu, double(j) / nv));
  auto at = [&](int i, int j) { return grid[size_t(i) * (nv + 1) + j]; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      double d1 = norm(sub(at(i, j), at(i + 1, j + 1))), d2 = norm(sub(at(i + 1, j), at(i, j + 1)));
      s.covering = std::max(s.covering, 0.5 * std::max(d1, d2));
    }
  s.points.insert(s.points.end(), grid.begin(), grid.end());
}

// Curved cells bulge past their corners by the sagitta (about d^2 / 8R,
// well under 1e-3 at the spacings used); add that and 5% to the covering.
SurfaceSamples finish(SurfaceSamples s) {
  s.covering = s.covering * 1.05 + 1e-3;
  return s;
}

// Two unit vectors completing `d` (unit) to an orthonormal basis.
void basis(const V3& d, V3& e1, V3& e2) {
  V3 helper = std::fabs(d[0]) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  e1 = normalize(cross(d, helper));
  e2 = cross(d, e1);
}

// Signed distance to the axis-aligned box |x_i| <= h_i by the closest point:
// outside, the distance to the clamped point; inside, to the nearest face.
double box_closest_point(const V3& p, const V3& h) {
  V3 c;
  bool outside = false;
  for (int i = 0; i < 3; ++i) {
    c[i] = std::clamp(p[i], -h[i], h[i]);
    outside = outside || c[i] != p[i];
  }
  if (outside) return norm(sub(p, c));
  return -std::min({h[0] - std::fabs(p[0]), h[1] - std::fabs(p[1]), h[2] - std::fabs(p[2])});
}

void box_faces(SurfaceSamples& s, double spacing, const V3& inner, double offset) {
  // Faces of the box with half extents `inner`, pushed out by `offset`.
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1}) {
      int j = (axis + 1) % 3, k = (axis + 2) % 3;
      patch(s, spacing, 2 * inner[j], 2 * inner[k], [&](double u, double v) {
        V3 p;
        p[axis] = sign * (inner[axis] + offset);
        p[j] = -inner[j] + 2 * inner[j] * u;
        p[k] = -inner[k] + 2 * inner[k] * v;
        return p;
      });
    }
}

Primitive sphere() {
  const double r = 0.8;
  return {"sphere", "sphere: {radius: 0.8}", r, [=](const V3& p) { return norm(p) - r; },
          [=](double sp) {
            SurfaceSamples s;
            patch(s, sp, kPi * r, 2 * kPi * r, [&](double u, double v) {
              double th = kPi * u, ph = 2 * kPi * v;
              return V3{r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)};
            });
            return finish(s);
          }};
}

Primitive box() {
  const V3 h{0.6, 0.4, 0.8};  // size [1.2, 0.8, 1.6]: full edges
  return {"box", "box: {size: [1.2, 0.8, 1.6]}", 0.8, [=](const V3& p) { return box_closest_point(p, h); },
          [=](double sp) {
            SurfaceSamples s;
            box_faces(s, sp, h, 0.0);
            return finish(s);
          }};
}

Primitive rounded_box() {
  // The rounded box is the inner box (half extents h - r) grown by r: its
  // distance is the inner box's minus r, and its surface is faces, quarter
  // cylinders along the 12 edges and sphere octants at the 8 corners.
  const double r = 0.15;
  const V3 a{0.6 - r, 0.4 - r, 0.8 - r};
  return {"rounded_box", "box: {size: [1.2, 0.8, 1.6], radius: 0.15}", 0.8,
          [=](const V3& p) { return box_closest_point(p, a) - r; },
          [=](double sp) {
            SurfaceSamples s;
            box_faces(s, sp, a, r);
            for (int i = 0; i < 3; ++i) {  // edges along axis i
              int j = (i + 1) % 3, k = (i + 2) % 3;
              for (int sj : {-1, 1})
                for (int sk : {-1, 1})
                  patch(s, sp, 2 * a[i], r * kPi / 2, [&](double u, double v) {
                    V3 p;
                    double th = v * kPi / 2;
                    p[i] = -a[i] + 2 * a[i] * u;
                    p[j] = sj * (a[j] + r * std::cos(th));
                    p[k] = sk * (a[k] + r * std::sin(th));
                    return p;
                  });
            }
            for (int sx : {-1, 1})
              for (int sy : {-1, 1})
                for (int sz : {-1, 1})
                  patch(s, sp, r * kPi / 2, r * kPi / 2, [&](double u, double v) {
                    double th = u * kPi / 2, ph = v * kPi / 2;
                    return V3{sx * (a[0] + r * std::sin(th) * std::cos(ph)),
                              sy * (a[1] + r * std::sin(th) * std::sin(ph)), sz * (a[2] + r * std::cos(th))};
                  });
            return finish(s);
          }};
}

Primitive torus() {
  const double R = 0.7, r = 0.25;
  return {"torus", "torus: {major_radius: 0.7, minor_radius: 0.25}", R + r,
          [=](const V3& p) {
            // Closest point of the core circle (radius R in the xy plane).
            double rho = std::hypot(p[0], p[1]);
            V3 c = rho > 0 ? V3{R * p[0] / rho, R * p[1] / rho, 0} : V3{R, 0, 0};
            return norm(sub(p, c)) - r;
          },
          [=](double sp) {
            SurfaceSamples s;
            patch(s, sp, 2 * kPi * (R + r), 2 * kPi * r, [&](double u, double v) {
              double ph = 2 * kPi * u, th = 2 * kPi * v;
              return V3{(R + r * std::cos(th)) * std::cos(ph), (R + r * std::cos(th)) * std::sin(ph), r * std::sin(th)};
            });
            return finish(s);
          }};
}

Primitive plane() {
  // normal [1, 2, 2] (normalised by the loader to [1, 2, 2] / 3), offset 0.3.
  const V3 n{1.0 / 3, 2.0 / 3, 2.0 / 3};
  const double off = 0.3;
  return {"plane", "plane: {normal: [1, 2, 2], offset: 0.3}", 1.5, [=](const V3& p) { return dot(p, n) - off; },
          [=](double sp) {
            // A patch big enough to hold the projection of every test point
            // (|p| <= 1.5 * 1.4 * sqrt(3) < 3.7 around the origin).
            SurfaceSamples s;
            V3 e1, e2;
            basis(n, e1, e2);
            const double L = 4.0;
            patch(s, 2 * sp, 2 * L, 2 * L, [&](double u, double v) {
              return add(mul(n, off), add(mul(e1, -L + 2 * L * u), mul(e2, -L + 2 * L * v)));
            });
            return finish(s);
          }};
}

Primitive cylinder() {
  const double R = 0.5, H = 0.7;  // height 1.4
  return {"cylinder", "cylinder: {radius: 0.5, height: 1.4}", 0.7,
          [=](const V3& p) {
            // Closest point of the rectangle [0, R] x [-H, H] in the (rho, z) half plane.
            double rho = std::hypot(p[0], p[1]), z = p[2];
            double rc = std::min(rho, R), zc = std::clamp(z, -H, H);
            if (rho > R || std::fabs(z) > H) return std::hypot(rho - rc, z - zc);
            return -std::min(R - rho, H - std::fabs(z));
          },
          [=](double sp) {
            SurfaceSamples s;
            patch(s, sp, 2 * kPi * R, 2 * H, [&](double u, double v) {
              double ph = 2 * kPi * u;
              return V3{R * std::cos(ph), R * std::sin(ph), -H + 2 * H * v};
            });
            for (int sign : {-1, 1})
              patch(s, sp, R, 2 * kPi * R, [&](double u, double v) {
                double rho = R * u, ph = 2 * kPi * v;
                return V3{rho * std::cos(ph), rho * std::sin(ph), sign * H};
              });
            return finish(s);
          }};
}

Primitive capsule() {
  const V3 a{-0.4, 0.1, -0.5}, b{0.3, -0.2, 0.6};
  const double r = 0.3;
  return {"capsule", "capsule: {a: [-0.4, 0.1, -0.5], b: [0.3, -0.2, 0.6], radius: 0.3}", 0.9,
          [=](const V3& p) {
            V3 ab = sub(b, a);
            double t = std::clamp(dot(sub(p, a), ab) / dot(ab, ab), 0.0, 1.0);
            return norm(sub(p, add(a, mul(ab, t)))) - r;
          },
          [=](double sp) {
            SurfaceSamples s;
            V3 ab = sub(b, a);
            double L = norm(ab);
            V3 d = mul(ab, 1 / L), e1, e2;
            basis(d, e1, e2);
            auto ring = [&](double ph) { return add(mul(e1, std::cos(ph)), mul(e2, std::sin(ph))); };
            patch(s, sp, 2 * kPi * r, L, [&](double u, double v) {
              return add(add(a, mul(d, L * v)), mul(ring(2 * kPi * u), r));
            });
            // Hemispheres facing away from the segment (the other halves are inside).
            for (int end = 0; end < 2; ++end)
              patch(s, sp, r * kPi / 2, 2 * kPi * r, [&](double u, double v) {
                double th = u * kPi / 2;
                V3 c = end == 0 ? a : b;
                V3 out = mul(d, end == 0 ? -std::cos(th) : std::cos(th));
                return add(c, mul(add(out, mul(ring(2 * kPi * v), std::sin(th))), r));
              });
            return finish(s);
          }};
}

}  // namespace

const std::vector<Primitive>& primitives() {
  static const std::vector<Primitive> p = {sphere(), box(), rounded_box(), torus(), plane(), cylinder(), capsule()};
  return p;
}

std::string PrimitiveScene::yaml() const {
  std::string head = "materials:\n  m1: {color: [0.9, 0.2, 0.1]}\n  m2: {color: [0.1, 0.3, 0.9]}\n";
  if (!transformed) return head + "scene: {" + prim->yaml + "}\n";
  return head + fmt::format(
                    "scene:\n"
                    "  union:\n"
                    "    - {{{}, scale: 1.3, rotate: {{axis: [1, 2, 3], degrees: 37}}, translate: [0.4, -0.7, 0.25], "
                    "material: m1}}\n"
                    "  rotate: [20, -35, 50]\n"
                    "  translate: [-0.3, 0.5, 0.8]\n"
                    "  scale: 0.8\n"
                    "  material: m2\n",
                    prim->yaml);
}

std::vector<test::Similarity> PrimitiveScene::chain() const {
  if (!transformed) return {};
  using test::Quat;
  // Euler [rx, ry, rz] degrees: about X, then Y, then Z (R = Rz Ry Rx).
  Quat euler = Quat::axis_angle({0, 0, 1}, 50) * Quat::axis_angle({0, 1, 0}, -35) * Quat::axis_angle({1, 0, 0}, 20);
  return {test::Similarity{0.8, euler, {-0.3, 0.5, 0.8}},
          test::Similarity{1.3, Quat::axis_angle({1, 2, 3}, 37), {0.4, -0.7, 0.25}}};
}

double PrimitiveScene::distance_scale() const {
  double s = 1;
  for (const auto& t : chain()) s *= t.scale;
  return s;
}

V3 PrimitiveScene::to_world(const V3& local) const {
  V3 p = local;
  auto c = chain();
  for (auto it = c.rbegin(); it != c.rend(); ++it) p = it->to_world(p);
  return p;
}

V3 PrimitiveScene::to_local(const V3& world) const {
  V3 p = world;
  for (const auto& t : chain()) p = t.to_local(p);
  return p;
}

void PrimitiveScene::world_box(double pad, V3& lo, V3& hi) const {
  double e = prim->extent * pad;
  lo = {1e30, 1e30, 1e30};
  hi = {-1e30, -1e30, -1e30};
  for (int corner = 0; corner < 8; ++corner) {
    V3 w = to_world({corner & 1 ? e : -e, corner & 2 ? e : -e, corner & 4 ? e : -e});
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], w[i]), hi[i] = std::max(hi[i], w[i]);
  }
}

SurfaceSamples PrimitiveScene::world_surface(double spacing) const {
  SurfaceSamples s = prim->surface(spacing / distance_scale());
  for (auto& p : s.points) p = to_world(p);
  s.covering *= distance_scale();
  return s;
}

std::vector<PrimitiveScene> primitive_scenes() {
  std::vector<PrimitiveScene> v;
  for (const auto& p : primitives()) {
    v.push_back({&p, false});
    v.push_back({&p, true});
  }
  return v;
}

}  // namespace sdfc::conformance
