#pragma once
#include <string>

#include "sdfc/source/source_value.hpp"

namespace sdfc {
// Reads a YAML scene file into a SourceValue tree. Throws SceneError with a
// location for a missing/unreadable file, a directory, binary junk or a YAML
// syntax error (tabs, bad indentation, unclosed brackets, duplicate keys).
SourceValue load_yaml_file(const std::string& path);
// Same for text already in memory; `name` is used in locations.
SourceValue load_yaml_text(const std::string& text, const std::string& name);
}  // namespace sdfc
