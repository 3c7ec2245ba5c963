#pragma once
// A kind's parameter as people who write scenes see it: the node reference
// of docs/scene-format.md is generated from these, and a test checks that a
// node written without the parameter gets this default.
#include <string_view>

namespace sdfc::kinds {

struct ParamDoc {
  std::string_view name;      // the YAML key
  std::string_view type;      // "number", "vec3", "integer", "bool", "one of a|b|c", "node", "list of nodes"
  std::string_view fallback;  // the default as a scene writes it; empty: required; "(...)": said in words
  std::string_view range;     // e.g. "> 0", "1 to 64"; empty: any
  std::string_view what;      // one line for people who make images
};

}  // namespace sdfc::kinds
