#pragma once
// Writing a whole top-level section (the viewer's `bookmarks:`) into a scene
// file: the section's own lines are replaced, or the section is added at the
// end of the file when it has none; every other line stays byte for byte.
#include <string>

#include "sdfc/source/source_value.hpp"

namespace sdfc {

// `text` with the top-level section `key` replaced by `block` (its whole
// text, "key:\n  - ...\n"). The section runs from its key's line to the next
// top-level key, less the comment and blank lines just before that key.
// `root` is `text` as loaded. A file that is not a block map with its keys
// at the start of their lines (a flow map `{...}`) is a SceneError.
std::string replace_section(const std::string& text, const SourceValue& root, const std::string& key,
                            const std::string& block);

}  // namespace sdfc
