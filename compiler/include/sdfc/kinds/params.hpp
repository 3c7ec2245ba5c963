#pragma once
// Named reads of the parameters that passes outside the descriptions need
// (each kind's description keeps its layout and defines its reads here).
#include <array>
#include <cstddef>
#include <vector>

#include "sdfc/ir/graph.hpp"

namespace sdfc::kinds {

// A material node's material: its index in the render plan's materials.
int material_id(const ir::Node& material);
// A displace node's expression: its index in Graph::expressions.
size_t displacement(const ir::Node& displace);
// A blend_* node's style: 0 cubic, 1 exponential, 2 chamfer, 3 round, 4 columns, 5 stairs.
int blend_style(const ir::Node& blend);
// A smooth_union/intersection/difference node's blend radius.
double smooth_radius(const ir::Node& smooth);
// A translate node's offset.
std::array<double, 3> translation(const ir::Node& translate);
// A scale node's factor, from the node or from its parameters alone.
double scale_factor(const std::vector<double>& scale_params);
// A step_factor node's factor on the distance.
double step_factor(const ir::Node& step);
// A sphere's radius.
double sphere_radius(const ir::Node& sphere);
// A box's half extents and the radius of its rounded edges.
std::array<double, 3> box_half_extent(const ir::Node& box);
double box_edge_radius(const ir::Node& box);

}  // namespace sdfc::kinds
