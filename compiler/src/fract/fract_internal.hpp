#pragma once
// Shared by the .fract reader's files; not a public interface.
#include <string>

namespace sdfc::fract {
// Moves `key` (and, where the format changed, `value`) to its 2.20 form.
void apply_renames(std::string& key, std::string& value, double version);
}  // namespace sdfc::fract
