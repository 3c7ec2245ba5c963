#pragma once
// Bounds, class, Lipschitz constant and cost of the domain operations and
// blends (issue 9).
#include <optional>

#include "sdfc/ir/graph.hpp"

namespace sdfc::passes::detail {
// `kid(i)` gives child i's properties as its parent sees them (after any
// correction). nullopt for other kinds. Throws SceneError for operations that
// cannot be bounded (a repeat period smaller than its child).
std::optional<ir::Props> domain_props(const ir::Graph& g, const ir::Node& n,
                                      const std::function<ir::Props(size_t)>& kid);
}  // namespace sdfc::passes::detail
