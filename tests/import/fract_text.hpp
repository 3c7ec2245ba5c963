#pragma once
// A 2.20 (or other version's) "only modified parameters" .fract made from its sections' lines,
// its import, and the first error an import reports.
#include <string>

#include "sdfc/fract/import.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::fract::fract_text {

inline std::string fract(const std::string& main, const std::string& fractal1 = "", const std::string& fractal2 = "",
                         const std::string& version = "2.20") {
  return "# Mandelbulber settings file\n# version " + version + "\n# only modified parameters\n[main_parameters]\n" + main +
         "[fractal_1]\n" + fractal1 + "[fractal_2]\n" + fractal2;
}

inline Imported imported(const std::string& text) { return import_scene(parse_text(text, "t.fract")); }

inline std::string error_of(const std::string& text) {
  try {
    imported(text);
  } catch (const SceneError& e) {
    return e.diagnostics().at(0).message;
  }
  return "no error";
}

}  // namespace sdfc::fract::fract_text
