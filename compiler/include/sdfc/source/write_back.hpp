#pragma once
// Writing changed values back into a scene file: only the characters of each
// changed number are replaced (found by the value's source location), so the
// comments, order and formatting of everything else stay byte for byte.
#include <string>
#include <vector>

#include "sdfc/source/source_value.hpp"

namespace sdfc {

struct ValueEdit {
  std::string path;  // as for --unlock: "scene.union[1].sphere.radius"
  std::string text;  // the new value as it should appear in the file, e.g. "0.75"
};

// `text` with each edited value's characters replaced. `root` is `text` as
// loaded (load_yaml_text). A path that names no scalar, a value whose
// characters are not where its location says (a multi-line or escaped
// string), or new text that is not one plain YAML word is a SceneError.
std::string rewrite_values(const std::string& text, const SourceValue& root, const std::vector<ValueEdit>& edits);

// The shortest text that reads back as exactly `x` ("0.75", "2", "-1e-05").
std::string yaml_number(double x);

// Replaces `path` by `text` through a temporary file and a rename, unless the
// file no longer holds `loaded` (someone changed it since): then nothing is
// written and it returns false.
bool save_if_unchanged(const std::string& path, const std::string& loaded, const std::string& text);

}  // namespace sdfc
