// Reference (double, CPU) orbit colour of the fractal kinds: the orbit trap
// (the smallest measure of the orbit against the trap's shape: by default
// its smallest |coordinate|) and the smooth iteration count,
// written from the formulas independently of stdlib/fractal_traps.cl.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "sdfc/formula/evaluate.hpp"
#include "sdfc/ir/fractal_math.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference {

namespace {

double len(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The trap's measure of one orbit point (the trap is its smallest value).
double measure(const ir::TrapShape& t, const Vec3& z) {
  using K = ir::TrapShape::Kind;
  Vec3 q{z[0] - t.point[0], z[1] - t.point[1], z[2] - t.point[2]};
  Vec3 d{t.direction[0], t.direction[1], t.direction[2]};
  switch (t.kind) {
    case K::Point: return len(q);
    case K::Plane: return std::fabs(dot(q, d));
    case K::Line: return std::sqrt(std::max(dot(q, q) - dot(q, d) * dot(q, d), 0.0));
    case K::Sphere: return std::fabs(len(q) - t.radius);
    case K::Cross: break;
  }
  return std::min({std::fabs(z[0]), std::fabs(z[1]), std::fabs(z[2])});
}

// n steps, |z| = r after them, escape radius R, growth g per step (a power
// for power_law, else a factor); 1 when the orbit never escaped.
double smooth_iteration(int n, double r, double R, double g, bool power_law, int iterations) {
  if (r < R) return 1.0;
  double lR = std::log(std::max(R, 1.0001));
  double frac = power_law ? std::log(std::log(std::max(r, 1.0001)) / lR) : std::log(r / R);
  frac = std::clamp(frac / std::log(std::max(g, 1.0001)), 0.0, 1.0);
  return (n - frac) / iterations;
}

Vec3 bulb(const Vec3& z, double power) {
  double r = std::max(len(z), 1e-20);
  double th = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * power, ph = std::atan2(z[1], z[0]) * power;
  double rn = std::pow(r, power);
  return {rn * std::sin(th) * std::cos(ph), rn * std::sin(th) * std::sin(ph), rn * std::cos(th)};
}

void box_sphere_fold(Vec3& z, double fl, double min_r, double fixed_r) {
  for (double& c : z) c = c > fl ? 2 * fl - c : c < -fl ? -2 * fl - c : c;
  double r2 = dot(z, z), f = 1;
  if (r2 < min_r * min_r) f = fixed_r * fixed_r / (min_r * min_r);
  else if (r2 < fixed_r * fixed_r) f = fixed_r * fixed_r / r2;
  for (double& c : z) c *= f;
}

void sort_abs_descending(Vec3& z) {
  for (double& c : z) c = std::fabs(c);
  std::sort(z.begin(), z.end(), [](double a, double b) { return a > b; });
}

void tetra(Vec3& z) {
  if (z[0] + z[1] < 0) z = {-z[1], -z[0], z[2]};
  if (z[0] + z[2] < 0) z = {-z[2], z[1], -z[0]};
  if (z[1] + z[2] < 0) z = {z[0], -z[2], -z[1]};
}

Vec3 rows(const std::vector<double>& q, size_t at, const Vec3& v) {
  return {q[at] * v[0] + q[at + 1] * v[1] + q[at + 2] * v[2], q[at + 3] * v[0] + q[at + 4] * v[1] + q[at + 5] * v[2],
          q[at + 6] * v[0] + q[at + 7] * v[1] + q[at + 8] * v[2]};
}

}  // namespace

std::optional<OrbitColour> orbit_colour(const ir::Node& n, const Vec3& p, const ir::TrapShape& shape) {
  auto min_abs = [&](const Vec3& z) { return measure(shape, z); };
  using ir::Kind;
  const auto& q = n.params;
  double trap = 1e10;
  switch (n.kind) {
    case Kind::Mandelbulb:
    case Kind::Juliabulb: {
      double power = q[0], bailout = q[2];
      int iterations = int(q[1]), k = 0;
      Vec3 c = n.kind == Kind::Juliabulb ? Vec3{q[3], q[4], q[5]} : p, z = p;
      for (; k < iterations && len(z) < bailout; ++k) {
        Vec3 w = bulb(z, power);
        for (int i = 0; i < 3; ++i) z[i] = w[i] + c[i];
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, smooth_iteration(k, len(z), bailout, power, true, iterations)};
    }
    case Kind::Mandelbox: {
      int iterations = int(q[4]), k = 0;
      Vec3 c = q[5] != 0 ? Vec3{q[6], q[7], q[8]} : p, z = p;
      for (; k < iterations && dot(z, z) < 1e4; ++k) {
        box_sphere_fold(z, q[3], q[1], q[2]);
        for (int i = 0; i < 3; ++i) z[i] = q[0] * q[9 + i] * z[i] + c[i];
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, smooth_iteration(k, len(z), 100, std::fabs(q[0]), false, iterations)};
    }
    case Kind::QuaternionJulia: {
      // q = a + v (v = (i, j, k) parts); the point is x + y i + z j + slice k.
      double a = p[0], bailout = q[7];
      Vec3 v{p[1], p[2], q[6]};
      int degree = int(q[4]), iterations = int(q[5]), k = 0;
      auto r = [&] { return std::sqrt(a * a + dot(v, v)); };
      for (; k < iterations && r() < bailout; ++k) {
        double vv = dot(v, v);
        double an = degree == 3 ? a * (a * a - 3 * vv) : a * a - vv, vs = degree == 3 ? 3 * a * a - vv : 2 * a;
        for (int i = 0; i < 3; ++i) v[i] = v[i] * vs + q[1 + i];
        a = an + q[0];
        trap = std::min(trap, min_abs(Vec3{a, v[0], v[1]}));
      }
      return OrbitColour{trap, smooth_iteration(k, r(), bailout, degree, true, iterations)};
    }
    case Kind::Menger: {
      double scale = q[1], shift = scale - 1;
      Vec3 z = p;
      for (int i = 0; i < int(q[0]); ++i) {
        sort_abs_descending(z);
        for (double& c : z) c = scale * c - shift;
        if (z[2] < -0.5 * shift) z[2] += shift;
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, 1.0};
    }
    case Kind::Sierpinski: {
      Vec3 z = p;
      for (int i = 0; i < int(q[0]); ++i) {
        tetra(z);
        for (double& c : z) c = q[1] * c - (q[1] - 1);
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, 1.0};
    }
    case Kind::Kifs: {
      auto sym = ir::KifsSymmetry(int(q[0]));
      double scale = q[1], g = std::numbers::phi;
      Vec3 off{q[2], q[3], q[4]}, z = p, n1{-g, g - 1, 1}, n2{1, -g, g + 1};
      for (Vec3* m : {&n1, &n2}) {
        double l = len(*m);
        for (double& c : *m) c /= l;
      }
      auto reflect = [](Vec3& z, const Vec3& m) {
        double t = dot(z, m);
        if (t > 0)
          for (int i = 0; i < 3; ++i) z[i] -= 2 * t * m[i];
      };
      for (int i = 0; i < int(q[5]); ++i) {
        z = rows(q, 6, z);
        if (sym == ir::KifsSymmetry::Tetrahedral) tetra(z);
        else if (sym == ir::KifsSymmetry::Icosahedral)
          for (int k = 0; k < 3; ++k) {
            for (double& c : z) c = std::fabs(c);
            reflect(z, n1);
            reflect(z, n2);
          }
        else sort_abs_descending(z);
        for (int k = 0; k < 3; ++k) z[k] = scale * z[k] - off[k] * (scale - 1);
        if (sym == ir::KifsSymmetry::Menger && z[2] < -0.5 * off[2] * (scale - 1)) z[2] += off[2] * (scale - 1);
        z = rows(q, 15, z);
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, 1.0};
    }
    case Kind::Hybrid: {
      int iterations = int(q[0]), steps = int(q[2]), k = 0;
      std::vector<int> pattern;
      for (int s = 0; s < steps; ++s)
        for (int r = 0; r < int(q[3 + s * ir::kHybridStepParams + 1]); ++r) pattern.push_back(s);
      const double escape = ir::hybrid_escape_radius(q[1]);
      Vec3 z = p;
      double growth = 2;
      bool power_law = false;
      for (; k < iterations && len(z) < escape; ++k) {
        const double* st = &q[3 + pattern[size_t(k) % pattern.size()] * ir::kHybridStepParams];
        if (st[0] == double(ir::HybridStep::Mandelbulb)) {
          z = bulb(z, st[2]);
          growth = st[2], power_law = true;
        } else {
          box_sphere_fold(z, st[5], st[3], st[4]);
          for (double& c : z) c *= st[2];
          growth = std::fabs(st[2]), power_law = false;
        }
        for (int i = 0; i < 3; ++i) z[i] += p[i];
        trap = std::min(trap, min_abs(z));
      }
      return OrbitColour{trap, smooth_iteration(k, len(z), escape, growth, power_law, iterations)};
    }
    case Kind::Formula: {  // a chain of steps (compiler/src/formula/)
      const formula::Chain& c = formula::chain(size_t(q[0]));
      formula::OrbitResult o = formula::evaluate(c, p, min_abs);
      return OrbitColour{o.trap, smooth_iteration(int(o.iterations), o.r, c.bailout, 2.0, formula::plan(c).log, c.iterations)};
    }
    default: return std::nullopt;
  }
}

}  // namespace sdfc::reference
