#pragma once
// A small text file (a generated job script) written like the images: to a
// temporary file beside it, then renamed, so `path` is never half-written.
#include <sdfrt/image_io.hpp>

#include <string>
#include <string_view>

namespace sdfrt {

// Throws IoError naming the path and the reason.
WriteReport write_text_file(const std::string& path, std::string_view text);

}  // namespace sdfrt
