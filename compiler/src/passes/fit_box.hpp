#pragma once
// The box camera.fit frames: the scene's bounds, or for a scene with
// unbounded parts (a floor plane) the union of its bounded parts.
#include <optional>

#include "sdfc/ir/module.hpp"

namespace sdfc::passes::detail {

std::optional<ir::Box3> fit_box(const ir::Module& m);

// Records fit_box on the plan's camera (camera.fit_lo/fit_hi).
void record_fit_box(ir::Module& m);

}  // namespace sdfc::passes::detail
