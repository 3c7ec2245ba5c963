// Packing an object set: the items' boxes, a bounding-volume hierarchy over
// them (median splits along the widest axis of the centres, so its depth is
// log2 of the item count), and the floats the kernel walks.
#include "sdfc/ir/object_set.hpp"

#include <algorithm>
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
