#pragma once
// The YAML document as yaml-cpp's parser reports it, kept in one flat array.
// It stands in for YAML::Load's node graph, which costs one heap node (and
// its shared_ptr bookkeeping) per value: on a 10 000-object scene building
// that graph took more time than scanning the text. Like that graph, an alias
// is the anchored value itself (same index, same mark), so the loader's walk
// expands, counts and locates values exactly as it did over YAML::Node.
#include <yaml-cpp/mark.h>

#include <cstdint>
#include <string>
#include <vector>

namespace sdfc::yaml_events {

struct Value {
  enum class Kind : std::uint8_t { Null, Scalar, Sequence, Map };
  Kind kind = Kind::Null;
  YAML::Mark mark;
  std::uint32_t tag = 0;  // index in `Document::tags` (yaml-cpp's tag text: "?" plain, "!" quoted)
  std::string scalar;     // Scalar text
  // Children in `Document::kids`: items, or key, value, key, value, ... (in file order)
  std::uint32_t first = 0, count = 0;
};

struct Document {
  std::vector<Value> values;
  std::vector<std::uint32_t> kids;
  std::vector<std::string> tags{"", "?", "!"};  // the usual ones first: most values share them
  std::int64_t root = -1;  // -1: no document
};

// Parses `text` (one document); throws yaml-cpp's exceptions as YAML::Load does.
Document parse(const std::string& text);

}  // namespace sdfc::yaml_events
