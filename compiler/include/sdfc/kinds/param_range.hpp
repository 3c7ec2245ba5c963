#pragma once
// The range a live value's slider spans, read from the kind description's
// documented range (ParamDoc::range, the text of the node reference), so the
// panel and `--unlock PATH` use the facts the docs state.
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "sdfc/kinds/param_doc.hpp"
#include "sdfc/source/source_value.hpp"

namespace sdfc::kinds {

// What a range text allows: "> 0", ">= 0, up to 100", "-8 to 8, |scale| > 1",
// "each -4 to 4". Clauses it cannot read ("less than fixed_radius") are left
// to the reader's own checks; nullopt when it reads none.
struct DocRange {
  double lo, hi;
  bool lo_open = false, hi_open = false;
  double abs_above = 0;  // "|x| > N": values in [-N, N] are refused
};
std::optional<DocRange> parse_doc_range(std::string_view text);

// A slider around x inside the documented range: x +- max(|x|, 1), stopping
// an eighth of the way short of an open end (a radius > 0 never reaches 0).
std::pair<double, double> slider_range(const DocRange& r, double x);

// The documented parameter a path names ("scene.union.1.sphere.radius",
// "scene.mandelbox.julia[0]"): the last key is the parameter, the key above
// it the kind. Null when the path does not end in a described kind's number.
const ParamDoc* documented_param(const std::vector<std::string>& steps);

}  // namespace sdfc::kinds
