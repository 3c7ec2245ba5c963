#pragma once
// Reference evaluation of an object set (sdfc/ir/object_set.hpp).
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference::detail {
Sample object_set_evaluate(const ir::Node& n, const Vec3& p);
}
