#include "sdfc/source/source_value.hpp"

#include <fmt/format.h>

namespace sdfc {

SourceValue::SourceValue() = default;
SourceValue::SourceValue(const SourceValue&) = default;
SourceValue::SourceValue(SourceValue&&) noexcept = default;
SourceValue& SourceValue::operator=(const SourceValue&) = default;
SourceValue& SourceValue::operator=(SourceValue&&) noexcept = default;
SourceValue::~SourceValue() = default;

const SourceValue* SourceValue::find(std::string_view key) const {
  for (const auto& [k, v] : entries)
    if (k.scalar == key) return &v;
  return nullptr;
}

SourceValue* SourceValue::find(std::string_view key) {
  for (auto& [k, v] : entries)
    if (k.scalar == key) return &v;
  return nullptr;
}

std::vector<std::string_view> SourceValue::keys() const {
  std::vector<std::string_view> out;
  for (const auto& e : entries) out.push_back(e.first.scalar);
  return out;
}

std::string SourceValue::kind_name() const {
  switch (kind) {
    case Kind::Null: return "nothing";
    case Kind::Scalar: return quoted ? fmt::format("the string \"{}\"", scalar) : fmt::format("'{}'", scalar);
    case Kind::Sequence: return fmt::format("a list of {}", items.size());
    case Kind::Map: return "a map";
  }
  return "?";
}

static void print_rec(const SourceValue& v, int indent, std::string& out) {
  std::string pad(indent * 2, ' ');
  std::string at = fmt::format("  @{}:{}", v.loc.line, v.loc.column);
  switch (v.kind) {
    case SourceValue::Kind::Null: out += "null" + at + "\n"; break;
    case SourceValue::Kind::Scalar:
      out += (v.quoted ? "\"" + v.scalar + "\"" : v.scalar) + at + "\n";
      break;
    case SourceValue::Kind::Sequence:
      out += "list" + at + "\n";
      for (const auto& it : v.items) {
        out += pad + "- ";
        print_rec(it, indent + 1, out);
      }
      break;
    case SourceValue::Kind::Map:
      out += "map" + at + "\n";
      for (const auto& [k, val] : v.entries) {
        out += pad + k.scalar + ": ";
        print_rec(val, indent + 1, out);
      }
      break;
  }
}

std::string print_source(const SourceValue& v) {
  std::string out;
  print_rec(v, 0, out);
  return out;
}

}  // namespace sdfc
