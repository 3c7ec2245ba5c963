// Fractal bounds from the estimator. The worst-case box of a Mandelbox
// (2 · folding_limit · (s + 1) / (s − 1)), of a Julia set (the escape
// radius) or of a hybrid (its bailout) can be several times the set itself:
// ±10.5 for a scale −1.5 Mandelbox whose surface reaches about ±4. The
// distance estimator says how far every point is from the surface, so a
// cell whose centre is farther from it than the cell's half-diagonal holds
// none of it. For each of the six faces of the box, a best-first search
// splits the cells that reach farthest that way until the first one the
// estimator cannot clear at the finest size: the face goes there.
//
// The estimator is "a bound in practice": the search trusts only half of
// it, and uses the Jacobian estimator (a true bound) where the scalar one
// is known to overshoot (the non-conformal Mandelbox). The finest cell is
// 1/128 of the worst-case box, and the result is padded by one more cell,
// so the bounds stay a little loose rather than clip the surface.
#include "fractal_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <queue>
#include <unordered_map>

#include "sdfc/kinds/registry.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::passes::detail {

namespace {

using ir::Box3;
using ir::Kind;
using V = std::array<double, 3>;

constexpr int kLevels = 7;          // the finest cell: 1/128 of the box per axis
// The share of the estimate the search believes is the description's
// bounds_trust: half, but all of a hybrid's, whose linear estimate r / dr
// already stays well below the distance (docs/scene-format.md, "hybrid").
// Estimator calls per face. A weak estimator (a hybrid's linear r / dr
// clears little space) would otherwise refine thousands of cells; when the
// budget runs out the face stays at the farthest cell still open, which
// holds everything not yet cleared, so the bound stays conservative.
constexpr int kBudget = 1500;

const kinds::Description* tightened(Kind k) {
  const kinds::Description* d = kinds::find(k);
  return d && d->bounds_trust > 0 ? d : nullptr;
}

// A cell: its level (0 = the whole box) and integer coordinates there.
struct Cell {
  int level;
  int x, y, z;
};

class Search {
 public:
  Search(const ir::Graph& g, ir::NodeId id, const Box3& box) : g_(g), id_(id), box_(box) {
    const kinds::Description* d = kinds::find(g.node(id).kind);
    trust_ = d->bounds_trust;
    bounds_distance_ = d->bounds_distance;
  }

  // How far the surface reaches along axis `a`, towards + (`up`) or −.
  double extent(int a, bool up) {
    auto reach = [&](const Cell& c) {
      double size = (box_.hi[a] - box_.lo[a]) / double(1 << c.level);
      int i = a == 0 ? c.x : a == 1 ? c.y : c.z;
      return up ? box_.lo[a] + size * (i + 1) : -(box_.lo[a] + size * i);
    };
    auto farther = [&](const Cell& l, const Cell& r) { return reach(l) < reach(r); };
    std::priority_queue<Cell, std::vector<Cell>, decltype(farther)> open(farther);
    open.push({0, 0, 0, 0});
    const long stop = evaluations_ + kBudget;
    while (!open.empty()) {
      Cell c = open.top();
      if (evaluations_ >= stop) return reach(c);
      open.pop();
      if (empty(c)) continue;
      if (c.level == kLevels) return reach(c);
      for (int k = 0; k < 8; ++k)
        open.push({c.level + 1, 2 * c.x + (k & 1), 2 * c.y + (k >> 1 & 1), 2 * c.z + (k >> 2 & 1)});
    }
    return up ? box_.lo[a] : -box_.hi[a];  // nothing at all: an empty box
  }

  double finest(int a) const { return (box_.hi[a] - box_.lo[a]) / double(1 << kLevels); }

 private:
  bool empty(const Cell& c) {
    uint64_t key = uint64_t(c.level) << 60 | uint64_t(c.x) << 40 | uint64_t(c.y) << 20 | uint64_t(c.z);
    auto hit = memo_.find(key);
    if (hit != memo_.end()) return hit->second;
    V centre, half;
    int at[3] = {c.x, c.y, c.z};
    for (int a = 0; a < 3; ++a) {
      double size = (box_.hi[a] - box_.lo[a]) / double(1 << c.level);
      centre[a] = box_.lo[a] + size * (at[a] + 0.5);
      half[a] = 0.5 * size;
    }
    ++evaluations_;
    double diag = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
    double d = bounds_distance_ ? bounds_distance_(g_.node(id_), centre) : reference::evaluate(g_, id_, centre).distance;
    bool out = std::isfinite(d) && trust_ * d > diag;
    memo_.emplace(key, out);
    return out;
  }

  const ir::Graph& g_;
  ir::NodeId id_;
  Box3 box_;
  double (*bounds_distance_)(const ir::Node&, const V&) = nullptr;
  double trust_ = 0.5;
  long evaluations_ = 0;
  std::unordered_map<uint64_t, bool> memo_;
};

// The same fractal is compiled again and again (every --set, every save in
// the viewer, every test): the answer is kept per kind and parameters.
std::mutex cache_mutex;
std::map<std::pair<int, std::vector<double>>, Box3> cache;

}  // namespace

Box3 fractal_bounds(const ir::Graph& g, ir::NodeId id, const Box3& worst) {
  const ir::Node& n = g.node(id);
  if (!tightened(n.kind) || n.animated() || !worst.finite()) return worst;
  auto key = std::make_pair(int(n.kind), n.params);
  {
    std::lock_guard<std::mutex> lock(cache_mutex);
    auto hit = cache.find(key);
    if (hit != cache.end()) return hit->second;
  }
  Search s(g, id, worst);
  Box3 b = worst;
  for (int a = 0; a < 3; ++a) {
    double pad = s.finest(a);
    b.hi[a] = std::min(worst.hi[a], s.extent(a, true) + pad);
    b.lo[a] = std::max(worst.lo[a], -s.extent(a, false) - pad);
    if (b.lo[a] > b.hi[a]) return worst;  // the estimator found no surface: keep the worst case
  }
  std::lock_guard<std::mutex> lock(cache_mutex);
  if (cache.size() > 256) cache.clear();
  cache.emplace(key, b);
  return b;
}

}  // namespace sdfc::passes::detail
