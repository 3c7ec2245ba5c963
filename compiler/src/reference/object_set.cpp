// Reference evaluation of an object set: every item, by brute force in
// double precision (no hierarchy), its primitives through their kinds'
// own reference distances, so the kernel's walk and culling are checked
// against the plain union they stand for.
#include "object_set.hpp"

#include <algorithm>
#include <cmath>

#include "sdfc/ir/object_set.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::reference::detail {

namespace {

namespace os = ir::object_set;

double prim_distance(const double* r, const Vec3& p) {
  Vec3 local{p[0] - r[1], p[1] - r[2], p[2] - r[3]};
  ir::Node n;
  if (int(r[0]) == os::kSphere) n.kind = ir::Kind::Sphere, n.params = {r[4]};
  else n.kind = ir::Kind::Box, n.params = {r[4], r[5], r[6], r[7]};
  return kinds::find(n.kind)->distance(n, local);
}

double item_distance(const os::View& v, size_t item, const Vec3& p) {
  const double* it = v.item(item);
  const size_t first = size_t(it[0]), count = size_t(it[1]);
  const double k = it[2];
  double d = prim_distance(v.prim(first), p);
  for (size_t i = 1; i < count; ++i) {  // the polynomial smooth minimum, as a smooth_union
    double b = prim_distance(v.prim(first + i), p);
    double h = std::max(k - std::fabs(d - b), 0.0) / k;
    d = std::min(d, b) - h * h * k / 4;
  }
  return d;
}

}  // namespace

Sample object_set_evaluate(const ir::Node& n, const Vec3& p) {
  const os::View v{n.params};
  Sample best{item_distance(v, 0, p), int(v.item(0)[3])};
  for (size_t i = 1; i < v.items(); ++i) {
    double d = item_distance(v, i, p);
    if (d < best.distance) best = {d, int(v.item(i)[3])};
  }
  return best;
}

}  // namespace sdfc::reference::detail
