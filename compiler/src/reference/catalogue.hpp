#pragma once
// Reference distances of the catalogue primitives, in double with plain
// branches (the stdlib versions are branch-free per lane).
#include <optional>

#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference::detail {
std::optional<double> catalogue_distance(const ir::Node& n, const Vec3& p);  // nullopt for other kinds
}
