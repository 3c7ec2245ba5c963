#pragma once
// Internal: make a compiler log readable by quoting the generated source
// around every ":LINE:COL: error" it mentions.
#include <string>

namespace sdfrt {

// For each distinct error location (at most a handful), returns
//   line 12, column 5: <compiler message>
//       9 | ...
//      ...
//   >  12 | offending line
//      13 | ...
// Empty when the log names no line.
std::string quote_error_lines(const std::string& build_log, const std::string& source);

}  // namespace sdfrt
