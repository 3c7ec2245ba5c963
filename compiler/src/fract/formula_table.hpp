#pragma once
// Mandelbulber's formulas by id: the name it shows, the bailout it uses when
// `use_default_bailout` is on, and the function that writes the sdfc node
// that makes the same shape. A formula without a writer is not supported
// yet: importing a file that uses it is an error naming it and its id. A new
// mapping (a formula-chain preset, say) is one more writer in the table.
#include <string>
#include <vector>

#include "sdfc/fract/fract_params.hpp"
#include "yaml_text.hpp"

namespace sdfc::fract {

// What a writer sees of one formula slot.
struct FormulaInput {
  const Params& fractal;  // [fractal_N]
  const Params& main;     // [main_parameters]
  int slot;               // N, 1 ... 9
  int id;
  std::string name;
  SourceLoc loc;          // formula_N's place (or [main_parameters] when absent)
  bool julia;             // julia_mode
  Vec3 julia_c;
  int iterations;         // N
  double bailout;         // the bailout Mandelbulber uses for this formula
  std::vector<std::string>* warnings;
  bool mirror_y;          // legacy_coordinate_system: the scene is mirrored y -> -y
  double version = 0;     // the file's Mandelbulber version (0: not given)
};

using FormulaWriter = Node (*)(const FormulaInput&);

// One formula iteration as formula-chain steps (YAML flow items, c added
// where Mandelbulber adds it), so that hybrids can string formulas together.
struct ChainPart {
  std::string steps;  // "{box_fold: {limit: 1}}, ..., add_c"
  std::string how;    // the comment: which keys, which rule
  int cap;            // sdfc's iteration cap for this formula alone
};
using ChainWriter = ChainPart (*)(const FormulaInput&);

struct Formula {
  int id;
  const char* name;
  double default_bailout;  // used when use_default_bailout is on
  FormulaWriter write;     // nullptr: not supported yet
  ChainWriter chain;       // nullptr: cannot be a step of a hybrid
  bool mirror_symmetric;   // the shape is its own mirror image in y -> -y (legacy_coordinate_system needs that)
};

// The row for `id`, or nullptr when Mandelbulber 2.20 has no such formula.
const Formula* find_formula(int id);
// The formula's name as Mandelbulber shows it, "formula id N" when unknown.
std::string formula_name(int id);

// "formula 'NAME' (id N)", or "formula id N" for an id 2.20 does not know.
std::string formula_label(int id);

// Throws: "formula 'NAME' (id N) with KEY = ... is not supported yet".
[[noreturn]] void unsupported_setting(const FormulaInput& in, const std::string& key, const std::string& what);

}  // namespace sdfc::fract
