// Packing an object set: the items' boxes, a bounding-volume hierarchy over
// them (median splits along the widest axis of the centres, so its depth is
// log2 of the item count), and the floats the kernel walks.
#include "sdfc/ir/object_set.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sdfc::ir::object_set {

namespace {

Box3 prim_box(const Prim& p) {
  Vec3d h = p.type == kSphere ? Vec3d{p.size[0], p.size[0], p.size[0]} : p.size;
  Box3 b;
  for (int i = 0; i < 3; ++i) b.lo[i] = p.center[i] - h[i], b.hi[i] = p.center[i] + h[i];
  return b;
}

// Where the item's surface can be: its primitives' boxes grown by how far
// the smooth union reaches below their minimum (smooth_union_reach, as a
// smooth union's bounds), and by a margin that keeps the
// kernel's float box test a lower bound.
Box3 item_box(const Item& it) {
  Box3 b = prim_box(it.prims[0]);
  for (const Prim& p : it.prims) b = b.united(prim_box(p));
  double scale = 1;
  for (int i = 0; i < 3; ++i) scale = std::max({scale, std::fabs(b.lo[i]), std::fabs(b.hi[i])});
  return b.padded(smooth_union_reach(it.prims.size(), it.blend) + 1e-5 * scale);
}

struct Build {
  const std::vector<Box3>& boxes;
  std::vector<size_t> order;  // item indices, leaf by leaf
  std::vector<std::array<double, kNodeFloats>> nodes;

  size_t node(size_t begin, size_t end, int depth) {
    if (depth > kMaxDepth) throw std::length_error("object set hierarchy too deep");
    Box3 b = boxes[order[begin]];
    Box3 centres{b.lo, b.lo};
    for (size_t i = begin; i < end; ++i) {
      const Box3& x = boxes[order[i]];
      b = b.united(x);
      for (int a = 0; a < 3; ++a) {
        double c = 0.5 * (x.lo[a] + x.hi[a]);
        centres.lo[a] = std::min(centres.lo[a], c), centres.hi[a] = std::max(centres.hi[a], c);
      }
    }
    size_t at = nodes.size();
    nodes.push_back({b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2], double(begin), double(end - begin)});
    if (end - begin <= kLeafItems) return at;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (centres.hi[a] - centres.lo[a] > centres.hi[axis] - centres.lo[axis]) axis = a;
    size_t mid = begin + (end - begin) / 2;
    auto centre = [&](size_t i) { return boxes[i].lo[axis] + boxes[i].hi[axis]; };
    std::nth_element(order.begin() + long(begin), order.begin() + long(mid), order.begin() + long(end),
                     [&](size_t x, size_t y) { return centre(x) < centre(y) || (centre(x) == centre(y) && x < y); });
    node(begin, mid, depth + 1);  // the left child follows its parent
    size_t right = node(mid, end, depth + 1);
    nodes[at][6] = double(right);
    nodes[at][7] = 0;
    return at;
  }
};

// The gather's hierarchy (kGatherFloats per node): each node holds the
// balls about the boxes kGatherLevels levels below one box of the hierarchy
// (or the leaves above that), left to right, so the gather visits the leaves
// in the order the boxes' walk does; a ball's index is its box's where that
// is a leaf, else -1 - the gather node holding its boxes. The balls are the
// ones the kernel tested about each box, computed as it did in floats and
// grown by a few of their last digits, so rounding cannot make them smaller.
struct GatherTree {
  const std::vector<std::array<double, kNodeFloats>>& nodes;
  std::vector<std::array<double, kGatherFloats>> out;

  static bool leaf(const std::array<double, kNodeFloats>& n) { return n[7] > 0; }
  void frontier(size_t n, int levels, std::vector<size_t>& to) const {
    if (levels == 0 || leaf(nodes[n])) return to.push_back(n);
    frontier(n + 1, levels - 1, to);  // the left child follows its parent
    frontier(size_t(nodes[n][6]), levels - 1, to);
  }
  size_t node(size_t n) {
    std::vector<size_t> below;
    frontier(n, kGatherLevels, below);
    size_t at = out.size();
    out.push_back({});
    for (size_t k = 0; k < size_t(kGatherWidth); ++k) {
      out[at][3 * kGatherWidth + k] = -1e30;  // no box: a ball no cone reaches
      if (k >= below.size()) continue;
      const auto& b = nodes[below[k]];
      float h[3], c[3], r2 = 0, far = 0;
      for (int i = 0; i < 3; ++i) {
        h[i] = 0.5f * (float(b[3 + i]) - float(b[i]));
        c[i] = float(b[i]) + h[i];
        r2 += h[i] * h[i];
        far = std::max(far, std::fabs(c[i]));
      }
      const float r = std::sqrt(r2);
      for (int i = 0; i < 3; ++i) out[at][i * kGatherWidth + k] = c[i];
      out[at][3 * kGatherWidth + k] = double(r) * (1 + 1e-6) + 1e-6 * double(std::max(far, r));
      const double ref = leaf(b) ? double(below[k]) : -1.0 - double(node(below[k]));
      out[at][4 * kGatherWidth + k] = ref;
    }
    return at;
  }
};

// A ball about each item (in the hierarchy's order) holding its shapes'
// balls as the gather measures them (a sphere's, or the one through a box's
// corners), grown by the blend's reach; as four arrays, x, y and z of the
// centres and the radii, each padded with balls no cone reaches.
void append_item_balls(std::vector<double>& q, const std::vector<Item>& items, const std::vector<size_t>& order) {
  const size_t n = items.size() + kItemBallPad;
  std::vector<double> balls(4 * n, 0.0);
  for (size_t k = items.size(); k < n; ++k) balls[3 * n + k] = -1e30;
  for (size_t k = 0; k < items.size(); ++k) {
    const Item& it = items[order[k]];
    const double reach = double(it.prims.size() - 1) * 0.25 * it.blend;
    auto radius = [&](const Prim& p) {
      return (p.type == kSphere ? p.size[0] : std::sqrt(p.size[0] * p.size[0] + p.size[1] * p.size[1] + p.size[2] * p.size[2])) + reach;
    };
    Vec3d lo = it.prims[0].center, hi = lo;
    for (const Prim& p : it.prims)
      for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p.center[i]), hi[i] = std::max(hi[i], p.center[i]);
    double r = 0;
    for (const Prim& p : it.prims) {
      double d2 = 0;
      for (int i = 0; i < 3; ++i) d2 += (p.center[i] - 0.5 * (lo[i] + hi[i])) * (p.center[i] - 0.5 * (lo[i] + hi[i]));
      r = std::max(r, std::sqrt(d2) + radius(p));
    }
    double far = 0;  // the centre is read as a float: grow the ball by more than that rounds
    for (int i = 0; i < 3; ++i) balls[size_t(i) * n + k] = 0.5 * (lo[i] + hi[i]), far = std::max(far, std::fabs(lo[i]) + std::fabs(hi[i]));
    balls[3 * n + k] = r * (1 + 1e-6) + 1e-6 * far;
  }
  q.insert(q.end(), balls.begin(), balls.end());
}

}  // namespace

std::vector<double> pack(std::vector<Item> items, size_t offset) {
  if (items.empty()) throw std::invalid_argument("an object set needs at least one item");
  std::vector<Box3> boxes;
  for (const Item& it : items) boxes.push_back(item_box(it));
  Build b{boxes, std::vector<size_t>(items.size()), {}};
  std::iota(b.order.begin(), b.order.end(), size_t(0));
  b.node(0, items.size(), 0);
  size_t prims = 0;
  for (const Item& it : items) prims += it.prims.size();
  std::vector<double> q = {double(offset), double(b.nodes.size()), double(items.size()), double(prims)};
  for (const auto& n : b.nodes) q.insert(q.end(), n.begin(), n.end());
  size_t first = 0;
  for (size_t i : b.order) {
    const Item& it = items[i];
    q.insert(q.end(), {double(first), double(it.prims.size()), it.blend, double(it.material)});
    first += it.prims.size();
  }
  for (size_t i : b.order)
    for (const Prim& p : items[i].prims)
      q.insert(q.end(), {double(p.type), p.center[0], p.center[1], p.center[2], p.size[0], p.size[1], p.size[2], p.edge});
  append_item_balls(q, items, b.order);
  GatherTree g{b.nodes, {}};
  g.node(0);
  for (const auto& n : g.out) q.insert(q.end(), n.begin(), n.end());
  return q;
}

double worst_cost(const std::vector<Item>& items) {
  constexpr int kCells = 32;       // per axis
  constexpr long kCellsPerItem = 512;  // an item over more cells counts everywhere
  Box3 all = item_box(items[0]);
  std::vector<Box3> boxes;
  for (const Item& it : items) boxes.push_back(item_box(it)), all = all.united(boxes.back());
  std::vector<int> count(size_t(kCells) * kCells * kCells, 0);
  long everywhere = 0;
  double most_prims = 1;
  auto cell = [&](double x, int a) {
    double w = all.hi[a] - all.lo[a];
    return w > 0 ? std::clamp(int((x - all.lo[a]) / w * kCells), 0, kCells - 1) : 0;
  };
  for (size_t i = 0; i < items.size(); ++i) {
    most_prims = std::max(most_prims, double(items[i].prims.size()));
    int lo[3], hi[3];
    long cells = 1;
    for (int a = 0; a < 3; ++a) lo[a] = cell(boxes[i].lo[a], a), hi[a] = cell(boxes[i].hi[a], a), cells *= hi[a] - lo[a] + 1;
    if (cells > kCellsPerItem) {
      ++everywhere;
      continue;
    }
    for (int x = lo[0]; x <= hi[0]; ++x)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int z = lo[2]; z <= hi[2]; ++z) ++count[(size_t(x) * kCells + size_t(y)) * kCells + size_t(z)];
  }
  const double overlap = double(*std::max_element(count.begin(), count.end()) + everywhere);
  const double depth = std::ceil(std::log2(double(items.size()) / double(kLeafItems) + 1));
  return 2 * depth * 24 + (overlap + double(kLeafItems)) * most_prims * 20;
}

}  // namespace sdfc::ir::object_set
