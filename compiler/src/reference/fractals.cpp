#include "fractals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "sdfc/ir/fractal_math.hpp"

namespace sdfc::reference::fractals {

namespace {

double len(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// White-Nylander power in spherical coordinates.
Vec3 bulb_power(const Vec3& z, double n, double* r_pow_n_minus_1) {
  double r = std::max(len(z), 1e-20);
  double theta = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * n;
  double phi = std::atan2(z[1], z[0]) * n;
  double rp = std::pow(r, n - 1);
  *r_pow_n_minus_1 = rp;
  double rn = rp * r;
  return {rn * std::sin(theta) * std::cos(phi), rn * std::sin(theta) * std::sin(phi), rn * std::cos(theta)};
}

// Box fold then sphere fold; returns the sphere fold's factor.
double box_sphere_fold(Vec3& z, double fl, double min_r, double fixed_r) {
  for (double& c : z) {
    if (c > fl) c = 2 * fl - c;
    else if (c < -fl) c = -2 * fl - c;
  }
  double r2 = dot(z, z), f = 1;
  if (r2 < min_r * min_r) f = (fixed_r * fixed_r) / (min_r * min_r);
  else if (r2 < fixed_r * fixed_r) f = (fixed_r * fixed_r) / r2;
  for (double& c : z) c *= f;
  return f;
}

struct Quat {
  double w, x, y, z;
};
Quat qmul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
double qnorm(const Quat& a) { return std::sqrt(a.w * a.w + a.x * a.x + a.y * a.y + a.z * a.z); }

Vec3 apply(const std::vector<double>& q, size_t at, const Vec3& v) {
  return {q[at] * v[0] + q[at + 1] * v[1] + q[at + 2] * v[2], q[at + 3] * v[0] + q[at + 4] * v[1] + q[at + 5] * v[2],
          q[at + 6] * v[0] + q[at + 7] * v[1] + q[at + 8] * v[2]};
}

// Reflect z in the plane with unit normal n (through the origin) if dot > 0.
void reflect_if_positive(Vec3& z, const Vec3& n) {
  double t = dot(z, n);
  if (t > 0)
    for (int i = 0; i < 3; ++i) z[i] -= 2 * t * n[i];
}

void tetra_folds(Vec3& z) {
  if (z[0] + z[1] < 0) z = {-z[1], -z[0], z[2]};
  if (z[0] + z[2] < 0) z = {-z[2], z[1], -z[0]};
  if (z[1] + z[2] < 0) z = {z[0], -z[2], -z[1]};
}

void sort_descending(Vec3& z) {
  for (double& c : z) c = std::fabs(c);
  std::sort(z.begin(), z.end(), [](double a, double b) { return a > b; });
}

}  // namespace

double juliabulb(const Vec3& p, const std::vector<double>& q) {
  double power = q[0], bailout = ir::bulb_estimator_radius(q[0], q[2]);
  int iterations = int(q[1]);
  Vec3 c{q[3], q[4], q[5]}, z = p;
  double dr = 1, r = len(z);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    double rp;
    Vec3 zn = bulb_power(z, power, &rp);
    dr = power * rp * dr;
    for (int k = 0; k < 3; ++k) z[k] = zn[k] + c[k];
    r = len(z);
  }
  double radius = ir::julia_set_radius(power, len(c));
  double r0 = len(p);
  if (r0 > 1.5 * radius) return r0 - radius;
  return 0.5 * std::log(std::max(r, 1e-20)) * r / dr;
}

double mandelbox(const Vec3& p, const std::vector<double>& q) {
  double scale = q[0];
  int iterations = int(q[4]);
  bool julia = q[5] != 0;
  Vec3 c = julia ? Vec3{q[6], q[7], q[8]} : p, axis{q[9], q[10], q[11]}, z = p;
  double dr = 1;
  for (int i = 0; i < iterations && dot(z, z) < 1e4; ++i) {
    double f = box_sphere_fold(z, q[3], q[1], q[2]);
    for (int k = 0; k < 3; ++k) z[k] = scale * axis[k] * z[k] + c[k];
    dr = dr * std::fabs(scale) * f + (julia ? 0 : 1);
  }
  return len(z) / std::fabs(dr);
}

double mandelbox_jacobian(const Vec3& p, const std::vector<double>& q) {
  using M3 = std::array<double, 9>;  // row-major: J[i][j] = d z_i / d p_j
  auto matmul = [](const M3& a, const M3& b) {
    M3 r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) r[i * 3 + j] += a[i * 3 + k] * b[k * 3 + j];
    return r;
  };
  double scale = q[0], fl = q[3], min2 = q[1] * q[1], fixed2 = q[2] * q[2];
  int iterations = int(q[4]);
  bool julia = q[5] != 0;
  Vec3 c = julia ? Vec3{q[6], q[7], q[8]} : p, z = p;
  M3 J{1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < iterations && dot(z, z) < 1e4; ++i) {
    // Each step's own Jacobian, multiplied onto the running one.
    M3 box{1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int k = 0; k < 3; ++k) {
      if (z[k] > fl) z[k] = 2 * fl - z[k], box[k * 4] = -1;
      else if (z[k] < -fl) z[k] = -2 * fl - z[k], box[k * 4] = -1;
    }
    J = matmul(box, J);
    double r2 = dot(z, z);
    M3 sphere{1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (r2 < min2) {
      for (int k = 0; k < 3; ++k) sphere[k * 4] = fixed2 / min2;
      for (double& v : z) v *= fixed2 / min2;
    } else if (r2 < fixed2) {
      double f = fixed2 / r2;  // d/dz (f2 z / |z|^2) = f (I - 2 z z^T / r2)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) sphere[a * 3 + b] = f * ((a == b ? 1 : 0) - 2 * z[a] * z[b] / r2);
      for (double& v : z) v *= f;
    }
    J = matmul(sphere, J);
    for (int a = 0; a < 3; ++a) {
      double m = scale * q[9 + a];
      z[a] = m * z[a] + c[a];
      for (int b = 0; b < 3; ++b) J[a * 3 + b] = m * J[a * 3 + b] + (!julia && a == b ? 1 : 0);
    }
  }
  // d = |z| / ||J||, with the Frobenius norm (>= the induced norm).
  double f2 = 0;
  for (double v : J) f2 += v * v;
  return len(z) / std::max(std::sqrt(f2), 1e-30);
}

double mandelbulb_numeric(const Vec3& p, const std::vector<double>& q) {
  double power = q[0], bailout = q[2];
  int iterations = int(q[1]);
  auto method = ir::DeMethod(int(q[3]));
  // |z| after passing the bailout, or after exactly `pin` steps.
  auto orbit = [&](const Vec3& c, int pin, int* steps) {
    Vec3 z = c;
    int n = 0;
    while (n < iterations && (pin >= 0 ? n < pin : len(z) < bailout)) {
      double rp;
      Vec3 zn = bulb_power(z, power, &rp);
      for (int k = 0; k < 3; ++k) z[k] = zn[k] + c[k];
      ++n;
    }
    *steps = n;
    return len(z);
  };
  const double eps = 1e-4;
  int n, nx, ny, nz;
  double r = orbit(p, -1, &n);
  int pin = method == ir::DeMethod::Gradient ? n : -1;
  double rx = orbit({p[0] + eps, p[1], p[2]}, pin, &nx);
  double ry = orbit({p[0], p[1] + eps, p[2]}, pin, &ny);
  double rz = orbit({p[0], p[1], p[2] + eps}, pin, &nz);
  double de;
  if (method == ir::DeMethod::Gradient) {
    double g = len({rx - r, ry - r, rz - r}) / eps;
    de = 0.5 * r * std::log(std::max(r, 1e-20)) / std::max(g, 1e-20);
  } else {
    auto G = [&](double rr, int k) { return std::log(std::max(rr, 1e-20)) / std::pow(power, k); };
    double g0 = G(r, n);
    double g = std::max(len({G(rx, nx) - g0, G(ry, ny) - g0, G(rz, nz) - g0}) / eps, 1e-20);
    de = method == ir::DeMethod::Potential ? 0.5 * g0 / g : 0.5 * std::sinh(g0) / (std::exp(g0) * g);
  }
  if (r < bailout) de = 0;  // never escaped: inside
  double radius = ir::mandelbulb_set_radius(power);
  double r0 = len(p);
  return r0 > 1.5 * radius ? r0 - radius : de;
}

double quaternion_julia(const Vec3& p, const std::vector<double>& q) {
  Quat c{q[0], q[1], q[2], q[3]}, z{p[0], p[1], p[2], q[6]};
  int degree = int(q[4]), iterations = int(q[5]);
  double bailout = q[7], md = 1, r = qnorm(z);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    md = degree * std::pow(r, degree - 1) * md;
    Quat zn = qmul(z, z);
    if (degree == 3) zn = qmul(zn, z);
    z = {zn.w + c.w, zn.x + c.x, zn.y + c.y, zn.z + c.z};
    r = qnorm(z);
  }
  double radius = ir::julia_set_radius(degree, qnorm(c));
  double r0 = std::sqrt(dot(p, p) + q[6] * q[6]);
  if (r0 > 1.5 * radius) return r0 - radius;
  return 0.5 * std::log(std::max(r, 1e-20)) * r / md;
}

double menger(const Vec3& p, const std::vector<double>& q) {
  int iterations = int(q[0]);
  double scale = q[1], shift = scale - 1, s = 1;
  Vec3 z = p;
  for (int i = 0; i < iterations; ++i) {
    sort_descending(z);
    for (double& c : z) c = scale * c - shift;
    if (z[2] < -0.5 * shift) z[2] += shift;
    s *= scale;
  }
  // Distance to the cube [-1, 1]^3.
  Vec3 d{std::fabs(z[0]) - 1, std::fabs(z[1]) - 1, std::fabs(z[2]) - 1};
  Vec3 out{std::max(d[0], 0.0), std::max(d[1], 0.0), std::max(d[2], 0.0)};
  return (len(out) + std::min(std::max({d[0], d[1], d[2]}), 0.0)) / s;
}

double sierpinski(const Vec3& p, const std::vector<double>& q) {
  int iterations = int(q[0]);
  double scale = q[1], s = 1;
  Vec3 z = p;
  for (int i = 0; i < iterations; ++i) {
    tetra_folds(z);
    for (double& c : z) c = scale * c - (scale - 1);
    s *= scale;
  }
  // The tetrahedron with vertices (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1):
  // the largest of its four face-plane distances.
  double faces = std::max({-z[0] - z[1] - z[2], z[0] + z[1] - z[2], -z[0] + z[1] + z[2], z[0] - z[1] + z[2]});
  return (faces - 1) / std::sqrt(3.0) / s;
}

double kifs(const Vec3& p, const std::vector<double>& q) {
  auto symmetry = ir::KifsSymmetry(int(q[0]));
  double scale = q[1], s = 1;
  Vec3 offset{q[2], q[3], q[4]}, z = p;
  int iterations = int(q[5]);
  const double g = std::numbers::phi;
  Vec3 n1{-g, g - 1, 1}, n2{1, -g, g + 1};
  for (Vec3* n : {&n1, &n2}) {
    double l = len(*n);
    for (double& c : *n) c /= l;
  }
  for (int i = 0; i < iterations; ++i) {
    z = apply(q, 6, z);
    switch (symmetry) {
      case ir::KifsSymmetry::Tetrahedral: tetra_folds(z); break;
      case ir::KifsSymmetry::Icosahedral:
        for (int k = 0; k < 3; ++k) {
          for (double& c : z) c = std::fabs(c);
          reflect_if_positive(z, n1);
          reflect_if_positive(z, n2);
        }
        break;
      case ir::KifsSymmetry::Octahedral:
      case ir::KifsSymmetry::Menger: sort_descending(z); break;
    }
    for (int k = 0; k < 3; ++k) z[k] = scale * z[k] - offset[k] * (scale - 1);
    if (symmetry == ir::KifsSymmetry::Menger && z[2] < -0.5 * offset[2] * (scale - 1)) z[2] += offset[2] * (scale - 1);
    z = apply(q, 15, z);
    s *= scale;
  }
  // The level-n cover of the attractor (inside |offset|) by balls.
  return (len(z) - len(offset)) / s;
}

double hybrid(const Vec3& p, const std::vector<double>& q) {
  int iterations = int(q[0]), steps = int(q[2]);
  double bailout = q[1];
  // The orbit's step sequence: each step `repeat` times, then around again.
  std::vector<int> pattern;
  for (int s = 0; s < steps; ++s)
    for (int k = 0; k < int(q[3 + s * ir::kHybridStepParams + 1]); ++k) pattern.push_back(s);
  Vec3 z = p;
  double dr = 1, r = len(z);
  const double escape = ir::hybrid_escape_radius(bailout);
  for (int i = 0; i < iterations && r < escape; ++i) {
    const double* st = &q[3 + pattern[i % pattern.size()] * ir::kHybridStepParams];
    if (st[0] == double(ir::HybridStep::Mandelbulb)) {
      double rp;
      Vec3 zn = bulb_power(z, st[2], &rp);
      dr = st[2] * rp * dr + 1;
      for (int k = 0; k < 3; ++k) z[k] = zn[k] + p[k];
    } else {
      double f = box_sphere_fold(z, st[5], st[3], st[4]);
      dr = dr * std::fabs(st[2]) * f + 1;
      for (int k = 0; k < 3; ++k) z[k] = st[2] * z[k] + p[k];
    }
    r = len(z);
  }
  double r0 = len(p);
  if (r0 > 2 * bailout) return r0 - bailout;  // the set lies inside the bailout ball
  return r / std::fabs(dr);
}

}  // namespace sdfc::reference::fractals
