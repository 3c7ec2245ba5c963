#pragma once
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {
// Emits `vec3 scene_normal_dual(vec3 p)`: the scene distance differentiated
// exactly in forward mode (every node carries its gradient), normalised. Only
// for scenes whose kinds all support it (ir/dual_normals.hpp; the front end
// checks).
std::string emit_scene_gradient(const ir::Module& m, const Literals& lit, std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
