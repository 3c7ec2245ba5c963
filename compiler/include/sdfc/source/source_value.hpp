#pragma once
// The scene as written: a tree of YAML values, each with its source location.
// This is the "AST" of `sdfc compile --emit ast`; --set overrides edit it
// before the schema check, so errors in overrides point at the override.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc {

struct UnlockSlot;  // sdfc/source/unlock.hpp

struct SourceValue {
  enum class Kind { Null, Scalar, Sequence, Map };

  // Out of line: clang with libstdc++ cannot instantiate the pair of this
  // still-incomplete type for implicit special members declared in the class.
  SourceValue();
  SourceValue(const SourceValue&);
  SourceValue(SourceValue&&) noexcept;
  SourceValue& operator=(const SourceValue&);
  SourceValue& operator=(SourceValue&&) noexcept;
  ~SourceValue();

  Kind kind = Kind::Null;
  SourceLoc loc;
  std::string scalar;   // Scalar text
  bool quoted = false;  // scalar was quoted: "8" is a string, 8 a number
  std::vector<SourceValue> items;                             // Sequence
  std::vector<std::pair<SourceValue, SourceValue>> entries;  // Map, in file order
  std::shared_ptr<UnlockSlot> unlock;  // set by mark_unlocked only, never by the loader

  bool is_map() const { return kind == Kind::Map; }
  bool is_seq() const { return kind == Kind::Sequence; }
  bool is_scalar() const { return kind == Kind::Scalar; }
  bool is_null() const { return kind == Kind::Null; }

  const SourceValue* find(std::string_view key) const;
  SourceValue* find(std::string_view key);
  std::vector<std::string_view> keys() const;
  std::string kind_name() const;  // "a map", "a list", "a number 3", ...
};

// Prints the tree with a location per value (for --emit ast).
std::string print_source(const SourceValue& v);

}  // namespace sdfc
