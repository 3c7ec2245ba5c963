#include "program_cache/build_log_context.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace sdfrt {
namespace {

constexpr int kLinesBefore = 3;
constexpr int kLinesAfter = 1;
// Later errors are usually consequences of the first ones.
constexpr std::size_t kMaxQuotedErrors = 8;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace

std::string quote_error_lines(const std::string& build_log, const std::string& source) {
  // Drivers disagree on the order: clang prints "file:6:18: error: ...",
  // PoCL "error: file:6:18: ...". Accept both; skip warnings and notes.
  static const std::regex location(
      R"((^|\n)((?:fatal )?error: )?[^\n]*?:(\d{1,8}):(\d{1,8}): ((?:fatal )?error: )?([^\n]*))");
  const auto lines = split_lines(source);
  const int line_count = static_cast<int>(lines.size());
  const int number_width = static_cast<int>(std::to_string(std::max(line_count, 1)).size());

  std::set<std::pair<int, int>> seen;
  std::string out;
  for (auto it = std::sregex_iterator(build_log.begin(), build_log.end(), location);
       it != std::sregex_iterator() && seen.size() < kMaxQuotedErrors; ++it) {
    const auto& match = *it;
    if (!match[2].matched && !match[5].matched) continue;  // a warning or note
    const int line = std::stoi(match[3].str());
    const int column = std::stoi(match[4].str());
    if (line < 1 || line > line_count || !seen.insert({line, column}).second) continue;

    out += fmt::format("line {}, column {}: {}\n", line, column, match[6].str());
    const int first = std::max(1, line - kLinesBefore);
    const int last = std::min(line_count, line + kLinesAfter);
    for (int n = first; n <= last; ++n) {
      out += fmt::format("{} {:>{}} | {}\n", n == line ? '>' : ' ', n, number_width,
                         lines[static_cast<std::size_t>(n - 1)]);
      if (n == line && column >= 1) {
        // Caret under the column (tabs kept so it lines up in a terminal).
        std::string pad;
        const auto& text = lines[static_cast<std::size_t>(n - 1)];
        for (int c = 1; c < column && static_cast<std::size_t>(c - 1) < text.size(); ++c) {
          pad += text[static_cast<std::size_t>(c - 1)] == '\t' ? '\t' : ' ';
        }
        out += fmt::format("  {:>{}} | {}^\n", "", number_width, pad);
      }
    }
  }
  return out;
}

}  // namespace sdfrt
