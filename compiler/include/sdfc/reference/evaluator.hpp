#pragma once
// The CPU reference evaluator: the IR's distance in double precision, written
// independently of the OpenCL stdlib. Tests compare every OpenCL evaluator
// against it.
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "sdfc/ir/module.hpp"

namespace sdfc::reference {

using Vec3 = std::array<double, 3>;

struct Sample {
  double distance;
  int material;  // material id of the closest surface (0 = default)
  // Smooth blends: the share of each material (id, weight, summing
  // to 1) at this point; empty means all of `material`. Id 0 is a part no
  // material node has claimed yet, as for `material`.
  std::vector<std::pair<int, double>> shares = {};
};

Sample evaluate(const ir::Graph& g, ir::NodeId node, const Vec3& p);
inline double distance(const ir::Module& m, const Vec3& p) { return evaluate(*m.graph, m.root, p).distance; }

// The shading parameters at p: every material's parameters weighted by its
// share. Orbit traps are not evaluated here: a material with a palette shows
// the palette's colour at trap 0 (what non-fractal geometry shows).
struct Look {
  Vec3 albedo;
  double specular, shininess, reflectivity;
  int material;  // the nearest material, as evaluate() gives it
};
Look evaluate_material(const ir::Module& m, const Vec3& p);

// A fractal node's colour values at p (in the node's own frame): its orbit
// trap (the smallest distance along the orbit to the trap's shape; by
// default the smallest |coordinate|) and its smooth iteration count in
// [0, 1] (1: never escaped; the fold fractals never do). Empty for other
// kinds.
struct OrbitColour {
  double trap;
  double iteration;
};
std::optional<OrbitColour> orbit_colour(const ir::Node& fractal, const Vec3& p, const ir::TrapShape& shape = {});

}  // namespace sdfc::reference
