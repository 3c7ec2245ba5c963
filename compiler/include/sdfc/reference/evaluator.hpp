#pragma once
// The CPU reference evaluator: the IR's distance in double precision, written
// independently of the OpenCL stdlib. Tests compare every OpenCL evaluator
// against it.
#include <array>
#include <optional>

#include "sdfc/ir/module.hpp"

namespace sdfc::reference {

using Vec3 = std::array<double, 3>;

struct Sample {
  double distance;
  int material;  // material id of the closest surface (0 = default)
};

Sample evaluate(const ir::Graph& g, ir::NodeId node, const Vec3& p);
inline double distance(const ir::Module& m, const Vec3& p) { return evaluate(*m.graph, m.root, p).distance; }

// A fractal node's colour values at p (in the node's own frame): its orbit
// trap (smallest |coordinate| along the orbit) and its smooth iteration
// count in [0, 1] (1: never escaped; the fold fractals never do). Empty for
// other kinds.
struct OrbitColour {
  double trap;
  double iteration;
};
std::optional<OrbitColour> orbit_colour(const ir::Node& fractal, const Vec3& p);

}  // namespace sdfc::reference
