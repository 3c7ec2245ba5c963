#pragma once
// Named reads of the parameters that passes outside the descriptions need
// of a kind with children (its description keeps the layout).
#include <cstddef>

#include "sdfc/ir/graph.hpp"

namespace sdfc::kinds {

// A material node's material: its index in the render plan's materials.
int material_id(const ir::Node& material);
// A displace node's expression: its index in Graph::expressions.
size_t displacement(const ir::Node& displace);
// A blend_* node's style: 0 cubic, 1 exponential, 2 chamfer, 3 round, 4 columns, 5 stairs.
int blend_style(const ir::Node& blend);

}  // namespace sdfc::kinds
