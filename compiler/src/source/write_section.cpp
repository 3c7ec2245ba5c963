#include "sdfc/source/write_section.hpp"

#include <fmt/format.h>

#include <vector>

namespace sdfc {

namespace {
// The byte offset of each line's start, and one past the end.
std::vector<size_t> line_starts(const std::string& text) {
  std::vector<size_t> at{0};
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') at.push_back(i + 1);
  if (at.back() != text.size()) at.push_back(text.size());
  return at;
}
bool blank_or_comment(const std::string& line) {
  size_t i = line.find_first_not_of(" \t\r\n");
  return i == std::string::npos || line[i] == '#';
}
}  // namespace

std::string replace_section(const std::string& text, const SourceValue& root, const std::string& key,
                            const std::string& block) {
  bool block_map = root.is_map() || root.is_null();
  for (const auto& [k, v] : root.entries) block_map = block_map && k.loc.column == 1 && k.loc.line > 0;
  if (!block_map)
    fail(root.loc, fmt::format("cannot write the {} section: the file is not a map with its keys at the start of their lines", key),
         "write the scene's sections one per line ('camera: ...', 'scene: ...')");
  const std::vector<size_t> starts = line_starts(text);
  const int lines = int(starts.size()) - 1;
  const SourceValue* own = root.find(key);
  if (!own) {  // a new section at the end, after a line break
    std::string out = text;
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out + block;
  }
  int first = 0, next = lines + 1;  // 1-based lines: [first, next)
  for (const auto& [k, v] : root.entries) {
    if (k.scalar == key) first = k.loc.line;
  }
  for (const auto& [k, v] : root.entries)
    if (k.loc.line > first && k.loc.line < next) next = k.loc.line;
  auto line = [&](int l) { return text.substr(starts[size_t(l - 1)], starts[size_t(l)] - starts[size_t(l - 1)]); };
  while (next - 1 > first && blank_or_comment(line(next - 1))) --next;  // they belong to what follows
  const size_t from = starts[size_t(first - 1)], to = starts[size_t(next - 1)];
  std::string tail = text.substr(to);
  std::string head = text.substr(0, from) + block;
  if (!tail.empty() && !head.empty() && head.back() != '\n') head += '\n';
  return head + tail;
}

}  // namespace sdfc
