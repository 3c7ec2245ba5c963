// canonicalise: one spelling for equivalent trees, so CSE and folding find
// more. Nested unions (and intersections) are flattened into one n-ary node,
// duplicate children of min/max dropped (min(a, a) = a), commutative children
// sorted by a structural hash (smooth blends only when they have two), and transforms pushed to the order
//   material( translate( rotate( scale( geometry ))))
// using  R(T(t, x)) = T(Rt, R(x)),  S(T(t, x)) = T(st, S(x)),
//        S(R(x)) = R(S(x))  (uniform scale commutes),  X(material(x)) = material(X(x)).
#include <algorithm>
#include <cstring>
#include <unordered_map>

#include "rewrite.hpp"
#include "sdfc/kinds/params.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::passes {

namespace {

using ir::Kind;
using ir::NodeId;

uint64_t mix(uint64_t h, uint64_t v) { return (h ^ v) * 0x100000001b3ull; }

// Hash of a subtree's structure (kind, params, children's hashes), independent
// of node ids so the order is the same on every run.
class StructuralHash {
 public:
  explicit StructuralHash(const ir::Graph& g) : g_(g) {}
  uint64_t operator()(NodeId id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    const ir::Node& n = g_.node(id);
    uint64_t h = mix(0xcbf29ce484222325ull, uint64_t(n.kind));
    for (double p : n.params) {
      uint64_t bits;
      std::memcpy(&bits, &p, sizeof bits);
      h = mix(h, bits);
    }
    for (const auto& e : n.anim)
      if (e)
        for (char ch : expr::to_string(e)) h = mix(h, uint64_t(uint8_t(ch)));
    for (NodeId c : n.children) h = mix(h, (*this)(c));
    return memo_[id] = h;
  }

 private:
  const ir::Graph& g_;
  std::unordered_map<NodeId, uint64_t> memo_;
};

std::vector<double> rotate_vec(const std::vector<double>& m, const std::vector<double>& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

bool is_transform(Kind k) { return k == Kind::Translate || k == Kind::Rotate || k == Kind::Scale; }

NodeId canon(ir::Builder& b, Kind k, std::vector<double> params, std::vector<NodeId> kids, const SourceLoc& loc,
             const ir::Animation& anim) {
  const ir::Graph& g = b.graph();
  // Animated transforms stay where they are (their parameters cannot be
  // composed with others at compile time).
  if (is_transform(k) && anim.empty() && !g.node(kids[0]).animated()) {
    const ir::Node c = g.node(kids[0]);  // copy: the builder may grow the graph
    if (c.kind == Kind::Material) {
      NodeId inner = canon(b, k, params, c.children, loc, anim);
      return detail::fold_node(b, Kind::Material, c.params, {inner}, c.loc);
    }
    if (c.kind == Kind::Translate && (k == Kind::Rotate || k == Kind::Scale)) {
      std::vector<double> t = c.params;
      if (k == Kind::Rotate) t = rotate_vec(params, t);
      else for (double& x : t) x *= kinds::scale_factor(params);
      NodeId inner = canon(b, k, params, c.children, loc, anim);
      return detail::fold_node(b, Kind::Translate, t, {inner}, c.loc);
    }
    if (k == Kind::Scale && c.kind == Kind::Rotate) {
      NodeId inner = canon(b, k, params, c.children, loc, anim);
      return detail::fold_node(b, Kind::Rotate, c.params, {inner}, c.loc);
    }
  }
  if (k == Kind::Union || k == Kind::Intersection) {
    std::vector<NodeId> flat;
    for (NodeId c : kids) {
      const ir::Node& cn = g.node(c);
      if (cn.kind == k) flat.insert(flat.end(), cn.children.begin(), cn.children.end());
      else flat.push_back(c);
    }
    kids = std::move(flat);
  }
  // min and max are associative, commutative and idempotent, so their children
  // can be sorted and deduplicated. A smooth blend is commutative for two
  // children but neither associative (the fold order matters with three) nor
  // idempotent (smin(a, a) < a), so it is sorted only when it has two.
  bool plain = k == Kind::Union || k == Kind::Intersection;
  if (ir::is_commutative(k) && (plain || kids.size() == 2)) {
    StructuralHash hash(g);
    std::vector<std::pair<uint64_t, NodeId>> keyed;
    for (NodeId c : kids) keyed.push_back({hash(c), c});
    std::stable_sort(keyed.begin(), keyed.end(), [](auto& a, auto& b) { return a.first < b.first; });
    kids.clear();
    for (auto& [h, c] : keyed)
      if (!plain || std::find(kids.begin(), kids.end(), c) == kids.end()) kids.push_back(c);
  }
  return detail::fold_node(b, k, std::move(params), std::move(kids), loc, anim);
}

}  // namespace

ir::Module canonicalise(ir::Module m) {
  return detail::rewrite(std::move(m), [](ir::Builder& b, const ir::Node& n, std::vector<NodeId> kids) {
    return canon(b, n.kind, n.params, std::move(kids), n.loc, n.anim);
  });
}

}  // namespace sdfc::passes
