// Glass in the path integrator against optics computed here in double: a
// ball lens images a panel's edge where Snell's law on both surfaces puts
// it, a clear ball in a furnace neither creates nor loses light, and the
// light through its centre keeps the Fresnel transmittance at normal
// incidence times Beer-Lambert's exp(-absorption x 2 r).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "render_helpers.hpp"
#include "sdfc/codegen/kernel_abi.hpp"

namespace sdfc {
namespace {

using test::render_text;
using V = std::array<double, 3>;

double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V mad(const V& a, const V& b, double s) { return {a[0] + b[0] * s, a[1] + b[1] * s, a[2] + b[2] * s}; }
V unit(const V& a) { double l = std::sqrt(dot(a, a)); return {a[0] / l, a[1] / l, a[2] / l}; }

// Snell's law for a unit d onto a unit n facing it; eta = n_from / n_to.
std::optional<V> refract(const V& d, const V& n, double eta) {
  double ci = -dot(d, n), s2 = eta * eta * (1 - ci * ci);
  if (s2 > 1) return std::nullopt;
  return unit(mad(V{d[0] * eta, d[1] * eta, d[2] * eta}, n, eta * ci - std::sqrt(1 - s2)));
}

constexpr int kSize = 64;
constexpr double kFov = 30, kIor = 1.5, kPanelY = 4, kEdgeX = 0.5;
const V kEye{0, -6, 0};

// The camera ray through continuous pixel coordinates (px, py) (the
// kernel's pinhole: forward +y, right +x, up +z).
V camera_ray(double px, double py) {
  double ta = std::tan(kFov * M_PI / 360);
  return unit({(2 * px / kSize - 1) * ta, 1, (1 - 2 * py / kSize) * ta});
}

// Where a camera ray, refracted into the unit ball at the origin and out of
// it, meets the panel plane y = kPanelY (x only); nullopt if it misses the
// ball or is reflected inside.
std::optional<double> panel_x_through_ball(const V& d) {
  double b = dot(kEye, d), disc = b * b - (dot(kEye, kEye) - 1);
  if (disc < 0) return std::nullopt;
  V p = mad(kEye, d, -b - std::sqrt(disc));
  auto d2 = refract(d, p, 1 / kIor);
  if (!d2) return std::nullopt;
  V q = mad(p, *d2, -2 * dot(p, *d2));  // the chord's other end
  auto d3 = refract(*d2, V{-q[0], -q[1], -q[2]}, kIor);
  if (!d3 || (*d3)[1] <= 0) return std::nullopt;
  return mad(q, *d3, (kPanelY - q[1]) / (*d3)[1])[0];
}

std::string ball_scene(const std::string& glass, const std::string& panel_at, int samples) {
  return fmt::format(
      "camera: {{position: [0, -6, 0], target: [0, 0, 0], up: [0, 0, 1], fov: {}}}\n"
      "render: {{width: {}, height: {}, samples: {}, gamma: 1, integrator: path, max_bounces: 8}}\n"
      "background: [0, 0, 0]\nlights: []\n"
      "materials:\n  clear: {{glass: {}}}\n  panel: {{color: [0, 0, 0], emission: [1, 1, 1]}}\n"
      "scene:\n  union:\n    - sphere: {{radius: 1}}\n      material: clear\n"
      "    - box: {{size: [20, 0.2, 20]}}\n      translate: [{}, {}, 0]\n      material: panel\n",
      kFov, kSize, kSize, samples, glass, panel_at, kPanelY);
}

// A glowing panel covers x > 0.5 behind a glass ball. The ball inverts it:
// inside its disc the bright part lies left of the edge's image. In each
// row the rendered edge (half the transmitted level, between pixel centres)
// sits where Snell's law on both surfaces puts it, within one pixel.
TEST(PathGlass, BallLensImagesAnEdgeWhereSnellPutsIt) {
  auto r = render_text(ball_scene(fmt::format("{{ior: {}}}", kIor), fmt::format("{}", kEdgeX + 10), 256));
  int rows = 0;
  for (int y = 22; y <= 42; y += 2) {
    const double py = y + 0.5;
    // the analytic edge: bisection on x_panel - kEdgeX along the row, left part of the disc
    auto f = [&](double px) { return *panel_x_through_ball(camera_ray(px, py)) - kEdgeX; };
    double lo = 16, hi = 30;  // inside the disc (it spans about 12..52) on either side of the edge
    ASSERT_GT(f(lo), 0) << "row " << y;
    ASSERT_LT(f(hi), 0) << "row " << y;
    for (int i = 0; i < 60; ++i) (f(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    const double edge = 0.5 * (lo + hi);  // in continuous pixel coordinates
    // the transmitted level: Fresnel at the two surfaces the edge's ray crosses is close to normal incidence
    const double level = r.image.at(0, int(edge) - 4, y);
    ASSERT_GT(level, 0.7) << "row " << y << ": the panel shows through the ball";
    std::optional<double> found;
    for (int x = int(edge) - 3; x <= int(edge) + 3 && !found; ++x) {
      float a = r.image.at(0, x, y), b = r.image.at(0, x + 1, y);
      if (a >= 0.5 * level && b < 0.5 * level) found = x + 0.5 + (a - 0.5 * level) / (a - b);
    }
    ASSERT_TRUE(found) << "row " << y << ": no edge near " << edge;
    EXPECT_NEAR(*found, edge, 1.0) << "row " << y;
    ++rows;
  }
  EXPECT_EQ(rows, 11);
}

// Through the centre the ray crosses both surfaces at normal incidence and
// travels 2 r inside: green keeps (1 - F0)^2 with F0 = ((n - 1) / (n + 1))^2,
// red is dimmed by the colour given at a distance (0.5 after 2 units).
TEST(PathGlass, CentreTransmitsFresnelTimesBeerLambert) {
  auto r = render_text(ball_scene("{ior: 1.5, color: [0.5, 1, 1], distance: 2}", "0", 256));
  double red = 0, green = 0;
  for (int y = 31; y <= 32; ++y)
    for (int x = 31; x <= 32; ++x) red += r.image.at(0, x, y) / 4, green += r.image.at(1, x, y) / 4;
  const double f0 = std::pow((kIor - 1) / (kIor + 1), 2);
  EXPECT_NEAR(green, (1 - f0) * (1 - f0), 0.02);
  EXPECT_NEAR(red / green, 0.5, 0.03);
}

// A clear ball under a uniform environment of 0.8, no lights: glass only
// redirects light, so every pixel on it converges to 0.8 (less the few
// paths still inside after max_bounces), never above; at 16 lanes and at
// one pixel per work-item (where the lane masks are plain integers).
TEST(PathGlass, ClearBallInAFurnaceKeepsTheEnvironment) {
  for (int width : {16, 1}) {
    auto r = render_text(
        "camera: {position: [0, -4, 0], target: [0, 0, 0], fov: 30}\n"
        "render: {width: 24, height: 24, samples: 128, gamma: 1, integrator: path, max_bounces: 12}\n"
        "background: [0.8, 0.8, 0.8]\nlights: []\n"
        "materials:\n  clear: {glass: {ior: 1.5}}\n"
        "scene: {sphere: {radius: 1}, material: clear}\n", width);
    double sum = 0;
    int n = 0;
    for (int y = 0; y < r.image.height; ++y)
      for (int x = 0; x < r.image.width; ++x) {
        if (r.image.at(abi::plane_index("hit"), x, y) < 1.0f) continue;
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(r.image.at(c, x, y)));
          sum += r.image.at(c, x, y);
        }
        ++n;
      }
    ASSERT_GT(n, 100);
    const double mean = sum / (3.0 * n);
    EXPECT_LE(mean, 0.8 * 1.005) << "glass created light at width " << width;
    EXPECT_GE(mean, 0.8 * 0.97) << "glass lost light at width " << width;
  }
}

}  // namespace
}  // namespace sdfc
