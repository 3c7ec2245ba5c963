#pragma once
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
// Emits material_of() (a select chain over the plan's materials) and
// shade_surface() (ambient folded to one constant, then one Blinn-Phong
// term per light, unrolled with its values as literals).
// bounds: the scene's padded bounds (null when unbounded), which end shadow rays.
std::string emit_shading(const ir::RenderPlan& plan, const Literals& lit, const ir::Box3* bounds,
                         std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
