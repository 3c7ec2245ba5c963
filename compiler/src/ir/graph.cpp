#include "sdfc/ir/graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "sdfc/kinds/params.hpp"

namespace sdfc::ir {

std::string_view to_string(DistanceClass c) {
  switch (c) {
    case DistanceClass::Exact: return "exact";
    case DistanceClass::Bound: return "bound";
    case DistanceClass::Lipschitz: return "lipschitz";
    case DistanceClass::Estimate: return "estimate";
  }
  return "?";
}

bool Box3::finite() const {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(lo[i]) || !std::isfinite(hi[i])) return false;
  return true;
}

bool Box3::empty() const {
  for (int i = 0; i < 3; ++i)
    if (lo[i] > hi[i]) return true;
  return false;
}

Box3 Box3::united(const Box3& o) const {
  Box3 r;
  for (int i = 0; i < 3; ++i) r.lo[i] = std::min(lo[i], o.lo[i]), r.hi[i] = std::max(hi[i], o.hi[i]);
  return r;
}

Box3 Box3::intersected(const Box3& o) const {
  Box3 r;
  for (int i = 0; i < 3; ++i) r.lo[i] = std::max(lo[i], o.lo[i]), r.hi[i] = std::min(hi[i], o.hi[i]);
  return r;
}

Box3 Box3::padded(double m) const {
  Box3 r = *this;
  for (int i = 0; i < 3; ++i) r.lo[i] -= m, r.hi[i] += m;
  return r;
}

NodeId Graph::add(Node n) {
  nodes_.push_back(std::move(n));
  return static_cast<NodeId>(nodes_.size() - 1);
}

std::vector<NodeId> Graph::postorder(NodeId root) const {
  // Iterative, so a 10 000-deep chain of unions cannot overflow the stack.
  std::vector<NodeId> order;
  if (root == kNoNode) return order;
  std::vector<char> state(nodes_.size(), 0);  // 0 new, 1 open, 2 done
  std::vector<std::pair<NodeId, size_t>> stack{{root, 0}};
  state[root] = 1;
  while (!stack.empty()) {
    auto& [id, next] = stack.back();
    const auto& kids = nodes_[id].children;
    if (next < kids.size()) {
      NodeId c = kids[next++];
      if (state[c] == 0) {
        state[c] = 1;
        stack.push_back({c, 0});
      }
    } else {
      state[id] = 2;
      order.push_back(id);
      stack.pop_back();
    }
  }
  return order;
}

std::vector<int> Graph::use_counts(NodeId root) const {
  std::vector<int> uses(nodes_.size(), 0);
  for (NodeId id : postorder(root))
    for (NodeId c : nodes_[id].children) ++uses[c];
  if (root != kNoNode) ++uses[root];
  return uses;
}

NodeId Builder::make(Kind k, std::vector<double> params, std::vector<NodeId> children, SourceLoc loc,
                     Animation anim) {
  const KindInfo& ki = info(k);
  // An object set's named parameters are a header; its data follows (sdfc/ir/object_set.hpp).
  if (k == Kind::ObjectSet ? params.size() < ki.params.size() : ki.params.size() != params.size())
    throw std::logic_error("IR: wrong parameter count for " + std::string(ki.name));
  // The key is the raw bytes of kind, params and children. -0.0 is folded to
  // 0.0 so the two spellings of zero share a node.
  std::string key;
  key.reserve(2 + params.size() * 8 + children.size() * 4 + 8);
  auto put = [&key](const void* p, size_t n) { key.append(static_cast<const char*>(p), n); };
  uint16_t kk = static_cast<uint16_t>(k);
  put(&kk, sizeof kk);
  uint32_t np = static_cast<uint32_t>(params.size());
  put(&np, sizeof np);
  for (double& v : params) {
    if (v == 0.0) v = 0.0;
    put(&v, sizeof v);
  }
  uint32_t nc = static_cast<uint32_t>(children.size());  // so the animation text below cannot pass for children
  put(&nc, sizeof nc);
  for (NodeId c : children) put(&c, sizeof c);
  // Animated parameters: their canonical text (a static node has none).
  bool any = false;
  for (const auto& e : anim) any = any || e;
  if (!any) anim.clear();
  if (any && anim.size() != params.size()) throw std::logic_error("IR: wrong animation count for " + std::string(ki.name));
  for (size_t i = 0; i < anim.size(); ++i)
    if (anim[i]) key += "\x01" + std::to_string(i) + ":" + expr::to_string(anim[i]);
  auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  NodeId id = g_.add(Node{k, std::move(params), std::move(children), std::move(loc), {}, std::move(anim)});
  index_.emplace(std::move(key), id);
  return id;
}

NodeId Builder::copy(const Node& n, std::vector<NodeId> children) {
  return make(n.kind, n.params, std::move(children), n.loc, n.anim);
}

bool Graph::animated(NodeId root) const {
  for (NodeId id : postorder(root)) {
    const Node& n = nodes_[id];
    if (n.animated()) return true;
    if (n.kind == Kind::Displace && expr::uses(expressions.at(kinds::displacement(n)), "time")) return true;
  }
  return false;
}

}  // namespace sdfc::ir
