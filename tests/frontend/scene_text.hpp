#pragma once
// Helpers for front-end tests: lower a scene given as text and capture the
// diagnostics it produces.
#include <string>
#include <vector>

#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::test {

inline ir::Module lower_text(const std::string& text) { return lower_scene(load_yaml_text(text, "t.yaml"), "t.yaml"); }

// The diagnostics of a scene that must fail (empty when it succeeds).
inline std::vector<Diagnostic> errors_of(const std::string& text) {
  try {
    lower_text(text);
  } catch (const SceneError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace sdfc::test
