#pragma once
// The node reference of docs/scene-format.md, generated from the kind
// table: per described kind its summary, distance class, parameters,
// example and picture, grouped by category.
#include <string>

namespace sdfc::cli {

// The Markdown between the reference's marker comments (without them).
std::string kind_reference_markdown();
// One line per described kind, "yaml<TAB>category<TAB>bounded|unbounded<TAB>example"
// (for the picture script).
std::string kind_list();

}  // namespace sdfc::cli
