#pragma once
// The SDF IR: an immutable, hash-consed DAG. Nodes live in a Graph and are
// named by NodeId; the Builder returns the existing node for an identical
// (kind, params, children) key, so equal subtrees are one node (libfive's
// tree/key.hpp does the same).
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "sdfc/expr/expr.hpp"
#include "sdfc/ir/node_kind.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::ir {

using NodeId = uint32_t;
inline constexpr NodeId kNoNode = std::numeric_limits<NodeId>::max();

// Distance-field classes, after Curv: exact Euclidean distance; a bound
// (never more than the distance: safe to step by); Lipschitz L > 1 (must be
// divided by L before stepping); estimate (a fractal DE, bound in practice).
enum class DistanceClass { Exact, Bound, Lipschitz, Estimate };
std::string_view to_string(DistanceClass c);

struct Box3 {
  std::array<double, 3> lo{-inf(), -inf(), -inf()};
  std::array<double, 3> hi{inf(), inf(), inf()};
  static constexpr double inf() { return std::numeric_limits<double>::infinity(); }
  bool finite() const;
  bool empty() const;
  static Box3 everything() { return {}; }
  static Box3 cube(double r) { return {{-r, -r, -r}, {r, r, r}}; }
  Box3 united(const Box3& o) const;
  Box3 intersected(const Box3& o) const;
  Box3 padded(double m) const;
};

// How far a chain of polynomial smooth blends of radius k over n inputs can
// reach below the nearest input: each of its n - 1 blends may lower the
// smaller of its two inputs by up to k/4. Bounds grow by it.
inline double smooth_union_reach(size_t n, double k) { return n < 2 ? 0.0 : double(n - 1) * k * 0.25; }

// Facts inferred per node by the infer_properties pass.
struct Props {
  bool known = false;
  Box3 bounds;             // where the surface can be; outside it d > 0
  DistanceClass cls = DistanceClass::Exact;
  double lipschitz = 1.0;  // L of the distance function
  double cost = 0.0;       // rough flops per evaluation
  // Where L > 1 and the scene asks for it, the emitter divides this node's
  // distance by L, so its parent sees a bound with L = 1. L may only hold
  // inside `lipschitz_region` (twist, bend, displace); outside it the
  // emitter uses the distance to that box, a bound since the surface lies inside.
  bool corrected = false;
  Box3 lipschitz_region;
};

// Animated parameters: empty, or one entry per parameter, null where the
// parameter is static. An animated parameter is an expression of `time`;
// params[i] then holds its value at time 0 (what the CPU reference
// evaluates unless asked for another time, see reference/at_time.hpp).
using Animation = std::vector<expr::ExprPtr>;

struct Node {
  Kind kind;
  std::vector<double> params;
  std::vector<NodeId> children;
  SourceLoc loc;  // where the first occurrence came from (not part of the key)
  Props props;
  Animation anim;  // part of the key (by the expressions' canonical text)
  bool animated() const { return !anim.empty(); }
  const expr::ExprPtr& animation(size_t i) const {
    static const expr::ExprPtr none;
    return i < anim.size() ? anim[i] : none;
  }
};

class Graph {
 public:
  const Node& node(NodeId id) const { return nodes_.at(id); }
  Node& mutable_node(NodeId id) { return nodes_.at(id); }
  size_t size() const { return nodes_.size(); }
  NodeId add(Node n);  // used by Builder only
  // Nodes reachable from root, children before parents (a topological order).
  std::vector<NodeId> postorder(NodeId root) const;
  // How many parents reference each node among those reachable from root.
  std::vector<int> use_counts(NodeId root) const;
  // Expressions that nodes refer to by index (displace); passes carry them over.
  // Does any node (or displace expression) reachable from root use time?
  bool animated(NodeId root) const;
  std::vector<expr::ExprPtr> expressions;

 private:
  std::vector<Node> nodes_;
};

class Builder {
 public:
  explicit Builder(Graph& g) : g_(g) {}
  // Returns the id of the node with this key, creating it if needed.
  NodeId make(Kind k, std::vector<double> params, std::vector<NodeId> children, SourceLoc loc = {},
              Animation anim = {});
  // Copies a node from another graph (children already mapped to this one).
  NodeId copy(const Node& n, std::vector<NodeId> children);
  Graph& graph() { return g_; }

 private:
  Graph& g_;
  std::unordered_map<std::string, NodeId> index_;  // key bytes -> node
};

}  // namespace sdfc::ir
