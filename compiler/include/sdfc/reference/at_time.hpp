#pragma once
// An animated module at one time: every animated parameter replaced by its
// value then, and `time` in displacement expressions by that number. The
// reference evaluator (and anything else that reads params) then sees the
// scene the kernel renders at that time. Bounds and Lipschitz constants are
// kept: they already hold for every time.
#include "sdfc/ir/module.hpp"

namespace sdfc::reference {

ir::Module at_time(const ir::Module& m, double time);

}  // namespace sdfc::reference
