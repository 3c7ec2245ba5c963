#include "kernel_text.hpp"

#include <fmt/format.h>

namespace sdfc::codegen {
namespace {

// `?` (trigraphs such as ??/), `*` (a `*/` ending a block comment), `\` (line
// continuation) and `%` (the escape itself) are encoded too.
bool passes_raw(unsigned char c) {
  if (c < 0x20 || c > 0x7e) return false;
  return c != '\\' && c != '?' && c != '*' && c != '%';
}

}  // namespace

std::string kernel_text(std::string_view text, size_t max_bytes) {
  std::string out;
  size_t n = text.size() < max_bytes ? text.size() : max_bytes;
  out.reserve(n + 8);
  for (size_t i = 0; i < n; ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (passes_raw(c)) out += static_cast<char>(c);
    else out += fmt::format("%{:02X}", c);
  }
  if (n < text.size()) out += "...";
  return out;
}

bool kernel_source_is_plain(std::string_view source) {
  for (char ch : source) {
    auto c = static_cast<unsigned char>(ch);
    if (c == '\n' || c == '\t') continue;
    if (c < 0x20 || c > 0x7e) return false;
  }
  return true;
}

}  // namespace sdfc::codegen
