#pragma once
// Tighter bounds for the fractals whose worst-case box is loose (the
// Mandelbox, the quaternion Julia set, KIFS, hybrids), found with the node's
// own distance estimator: every cell of the worst-case box that the
// estimator shows to be empty is cut away.
#include "sdfc/ir/graph.hpp"

namespace sdfc::passes::detail {

// The box that holds the surface of fractal node `id`, inside `worst` (the
// bounds from the set's worst case). Any other node, an animated one or an
// unbounded `worst` comes back as `worst`.
ir::Box3 fractal_bounds(const ir::Graph& g, ir::NodeId id, const ir::Box3& worst);

}  // namespace sdfc::passes::detail
