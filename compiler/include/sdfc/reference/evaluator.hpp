#pragma once
// The CPU reference evaluator: the IR's distance in double precision, written
// independently of the OpenCL stdlib. Tests compare every OpenCL evaluator
// against it.
#include <array>

#include "sdfc/ir/module.hpp"

namespace sdfc::reference {

using Vec3 = std::array<double, 3>;

struct Sample {
  double distance;
  int material;  // material id of the closest surface (0 = default)
};

Sample evaluate(const ir::Graph& g, ir::NodeId node, const Vec3& p);
inline double distance(const ir::Module& m, const Vec3& p) { return evaluate(*m.graph, m.root, p).distance; }

}  // namespace sdfc::reference
