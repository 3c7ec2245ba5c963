#pragma once
// Bounds, class and cost of the catalogue primitives (cone ... box_frame).
#include <optional>

#include "sdfc/ir/graph.hpp"

namespace sdfc::passes::detail {
std::optional<ir::Props> catalogue_props(const ir::Node& n);  // nullopt for other kinds
}
