#pragma once
// Object sets in the kernel (sdfc/ir/object_set.hpp): the call that walks
// one, and the scene data buffer that holds their numbers.
#include <set>
#include <string>
#include <vector>

#include "code_writer.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {

struct ObjectSetCode {
  std::string d;    // the distance variable
  std::string mat;  // the nearest item's material id (0: none inside the set)
};
// Declares the set's distance and material at point p; `where` ends the comment.
ObjectSetCode emit_object_set(const ir::Node& n, const std::string& p, const std::string& where, CodeWriter& w,
                              std::set<std::string>& used);

// scene_material: the record of material `id` (a real variable), as
// material_of gives it, with the reflectivity of that material.
std::string object_set_record(const std::string& id, const ir::Module& m, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used);

// Every object set's floats at its offset: what follows the frame block (and
// the unlocked values) in the frame buffer. Empty without object sets.
std::vector<float> scene_data(const ir::Module& m);
bool has_object_sets(const ir::Module& m);

// The prelude's addition: scene functions take the buffer after the time.
std::string scene_data_macros(bool animated, int unlocked);

}  // namespace sdfc::codegen::detail
