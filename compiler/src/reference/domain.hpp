#pragma once
// Reference evaluation of the domain operations and blends (issue 9).
#include <optional>

#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference::detail {
std::optional<Sample> domain_evaluate(const ir::Graph& g, const ir::Node& n, const Vec3& p);  // nullopt for other kinds
}
