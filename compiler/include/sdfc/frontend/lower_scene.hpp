#pragma once
#include "sdfc/ir/module.hpp"
#include "sdfc/source/source_value.hpp"

namespace sdfc {
// Checks the scene against the schema (docs/scene-format.md) and builds the
// IR and render plan. Reports every mistake it can find as one SceneError.
ir::Module lower_scene(const SourceValue& doc, const std::string& source_name);
}  // namespace sdfc
