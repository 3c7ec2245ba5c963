#pragma once
// The OpenCL C stdlib as embedded at build time (see stdlib/embed.cmake).
#include <string_view>
#include <vector>

namespace sdfc {
struct StdlibFile {
  std::string_view name;  // e.g. "primitives.cl"
  std::string_view text;
};
const std::vector<StdlibFile>& stdlib_files();
}  // namespace sdfc
