#pragma once
// `--set path=value` overrides, like Mandelbulber's -O: the path walks maps by
// key and lists by index (scene.union.0.mandelbulb.power), the value is YAML.
#include <string>
#include <vector>

#include "sdfc/source/source_value.hpp"

namespace sdfc {
// Applies "a.b.0.c=value". Missing map keys on the way are created (so
// render.width works without a render block); a bad path is a SceneError.
void apply_override(SourceValue& root, const std::string& assignment);
void apply_overrides(SourceValue& root, const std::vector<std::string>& assignments);
}  // namespace sdfc
