#pragma once
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {
// Emits `real scene_dist(vec3 p)` and, if with_material,
// `real scene_dist_mat(vec3 p, real* mat)`; adds the stdlib functions they
// call to `used`.
std::string emit_scene_functions(const ir::Module& m, const Literals& lit, std::set<std::string>& used);

// `real scene_material(vec3 p, mat_record* out)`: the blended material at p
// and the nearest material's id. Calls material_of, so it goes after the
// shading functions.
std::string emit_scene_material(const ir::Module& m, const Literals& lit, std::set<std::string>& used);

// `real scene_iterations(vec3 p)`: the iteration count of the nearest
// fractal at p, 0 where a non-fractal surface is nearest (the AOV).
std::string emit_scene_iterations(const ir::Module& m, const Literals& lit, std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
