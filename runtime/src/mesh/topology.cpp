// Edge bookkeeping by sorting one 64-bit key per directed edge (smaller
// vertex, larger vertex, direction bit), so a mesh of tens of millions of
// triangles needs 8 bytes per edge-use and no hash map.
#include <sdfrt/mesh/topology.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sdfrt::mesh {

namespace {

struct Parts {  // union-find over vertices
  std::vector<std::uint32_t> up;
  explicit Parts(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0u); }
  std::uint32_t root(std::uint32_t v) {
    while (up[v] != v) v = up[v] = up[up[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { up[root(a)] = root(b); }
};

}  // namespace

Topology check_topology(const Mesh& m) {
  if (m.vertices.size() >= (1u << 31)) throw std::length_error("check_topology: more than 2^31 vertices");
  Topology t;
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * m.triangles.size());
  Parts parts(m.vertices.size());
  std::vector<bool> used(m.vertices.size(), false);
  for (const Tri& tri : m.triangles) {
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) ++t.degenerate_triangles;
    for (int e = 0; e < 3; ++e) {
      std::uint64_t a = tri[e], b = tri[(e + 1) % 3];
      used[a] = true;
      parts.join(std::uint32_t(a), std::uint32_t(b));
      keys.push_back(a < b ? (a << 32 | b << 1) : (b << 32 | a << 1 | 1));
    }
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j] >> 1 == keys[i] >> 1) ++j;
    ++t.edges;
    if (j - i == 1) ++t.open_edges;
    else if (j - i > 2) ++t.overshared_edges;
    else if ((keys[i] & 1) == (keys[i + 1] & 1)) ++t.misoriented_edges;
    i = j;
  }
  std::size_t vertices = 0;
  for (std::uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) {
      ++vertices;
      if (parts.root(v) == v) ++t.parts;
    }
  t.euler = std::int64_t(vertices) - std::int64_t(t.edges) + std::int64_t(m.triangles.size());
  return t;
}

double volume(const Mesh& m) {
  double v = 0;
  for (const Tri& t : m.triangles) {
    const Vec3f &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    v += double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) + double(a[1]) * (double(b[2]) * c[0] - double(b[0]) * c[2]) +
         double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0]);
  }
  return v / 6;
}

double area(const Mesh& m) {
  double s = 0;
  for (const Tri& t : m.triangles) {
    const Vec3f &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    double u[3], w[3];
    for (int i = 0; i < 3; ++i) u[i] = double(b[i]) - a[i], w[i] = double(c[i]) - a[i];
    double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
    s += 0.5 * std::sqrt(x * x + y * y + z * z);
  }
  return s;
}

}  // namespace sdfrt::mesh
