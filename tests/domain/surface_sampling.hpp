#pragma once
// Brute-force distances for checking distance functions: the zero set of a
// field, sampled densely (sign changes along grid edges, refined by
// bisection), and the distance from a point to the nearest sample.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace sdfc::test {

using P3 = std::array<double, 3>;
using Field = std::function<double(const P3&)>;

struct Sampling {
  std::vector<P3> points;
  double spacing = 0;  // grid step: every surface point has a sample within spacing * sqrt(3)
};

inline Sampling sample_surface(const Field& f, const P3& lo, const P3& hi, int n) {
  Sampling s;
  double step = 0;
  for (int i = 0; i < 3; ++i) step = std::max(step, (hi[i] - lo[i]) / n);
  s.spacing = step;
  int nx[3];
  for (int i = 0; i < 3; ++i) nx[i] = int(std::ceil((hi[i] - lo[i]) / step)) + 1;
  auto at = [&](int x, int y, int z) { return P3{lo[0] + x * step, lo[1] + y * step, lo[2] + z * step}; };
  std::vector<double> v(size_t(nx[0]) * nx[1] * nx[2]);
  auto idx = [&](int x, int y, int z) { return (size_t(z) * nx[1] + y) * nx[0] + x; };
  for (int z = 0; z < nx[2]; ++z)
    for (int y = 0; y < nx[1]; ++y)
      for (int x = 0; x < nx[0]; ++x) v[idx(x, y, z)] = f(at(x, y, z));
  auto refine = [&](P3 a, P3 b, double fa) {
    for (int it = 0; it < 48; ++it) {
      P3 m{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
      if ((f(m) < 0) == (fa < 0)) a = m;
      else b = m;
    }
    s.points.push_back({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2});
  };
  for (int z = 0; z < nx[2]; ++z)
    for (int y = 0; y < nx[1]; ++y)
      for (int x = 0; x < nx[0]; ++x) {
        double a = v[idx(x, y, z)];
        int d[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (auto& e : d) {
          int X = x + e[0], Y = y + e[1], Z = z + e[2];
          if (X >= nx[0] || Y >= nx[1] || Z >= nx[2]) continue;
          double b = v[idx(X, Y, Z)];
          if ((a < 0) != (b < 0)) refine(at(x, y, z), at(X, Y, Z), a);
        }
      }
  return s;
}

inline double nearest(const std::vector<P3>& pts, const P3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const P3& s : pts) {
    double dx = s[0] - p[0], dy = s[1] - p[1], dz = s[2] - p[2];
    best = std::min(best, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(best);
}

// Deterministic pseudo-random points in a box (a small LCG: no seeds to manage).
inline std::vector<P3> points_in(const P3& lo, const P3& hi, int count, unsigned seed = 12345) {
  std::vector<P3> out;
  unsigned s = seed;
  auto u = [&] { s = s * 1664525u + 1013904223u; return (s >> 8) / double(1u << 24); };
  for (int i = 0; i < count; ++i) out.push_back({lo[0] + (hi[0] - lo[0]) * u(), lo[1] + (hi[1] - lo[1]) * u(), lo[2] + (hi[2] - lo[2]) * u()});
  return out;
}

}  // namespace sdfc::test
