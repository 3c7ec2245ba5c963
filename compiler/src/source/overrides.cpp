#include "sdfc/source/overrides.hpp"

#include <fmt/format.h>

#include "sdfc/source/yaml_loader.hpp"

namespace sdfc {

namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

bool is_index(const std::string& s) {
  return !s.empty() && s.size() < 9 && s.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

void apply_override(SourceValue& root, const std::string& assignment) {
  auto where = std::make_shared<const std::string>("--set " + assignment);
  size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    fail(SourceLoc(where, 0, 0), "expected --set path=value", "e.g. --set render.width=640");
  std::string path = assignment.substr(0, eq);
  SourceValue value = load_yaml_text(assignment.substr(eq + 1), "--set " + path);
  // Columns inside the value count from the start of the whole assignment.
  value.loc.column += static_cast<int>(eq + 1);

  SourceValue* cur = &root;
  std::string walked;
  size_t column = 1;  // of the current step inside the assignment
  for (const auto& part : split_path(path)) {
    if (part.empty())
      fail(SourceLoc(where, 1, 1), "empty step in path '" + path + "'", "");
    if (cur->is_seq()) {
      if (!is_index(part))
        fail(cur->loc, "'" + walked + "' is a list: expected an index, got '" + part + "'", "");
      size_t i = std::stoul(part);
      if (i >= cur->items.size())  // the mistake is in the override, not in the list
        fail(SourceLoc(where, 1, int(column)), "'" + walked + "' has " + std::to_string(cur->items.size()) +
                                                    " items; index " + part + " is past the end",
             fmt::format("the list is at {}", cur->loc.str()));
      cur = &cur->items[i];
    } else {
      if (cur->is_null()) cur->kind = SourceValue::Kind::Map;  // create missing blocks on the way
      if (!cur->is_map())
        fail(cur->loc, "'" + walked + "' is " + cur->kind_name() + ", so it has no '" + part + "'", "");
      SourceValue* next = cur->find(part);
      if (!next) {
        SourceValue key;
        key.kind = SourceValue::Kind::Scalar;
        key.scalar = part;
        key.loc = value.loc;
        SourceValue empty;
        empty.loc = value.loc;
        cur->entries.emplace_back(std::move(key), std::move(empty));
        next = &cur->entries.back().second;
      }
      cur = next;
    }
    walked += (walked.empty() ? "" : ".") + part;
    column += part.size() + 1;
  }
  *cur = std::move(value);
}

void apply_overrides(SourceValue& root, const std::vector<std::string>& assignments) {
  for (const auto& a : assignments) apply_override(root, a);
}

}  // namespace sdfc
