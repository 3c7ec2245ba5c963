#include "kernel_text.hpp"

#include <fmt/format.h>

namespace sdfc::codegen {
namespace {

// `\` (line continuation) and `%` (the escape itself) are always encoded;
// `?` only where it could start a trigraph (next to another `?`) and `*`
// only where it could open or close a block comment (next to a `/`), or at
// either end of the text, whose neighbours in the kernel are not known here.
// So `0.5 * x` stays readable in the kernel's comments.
bool passes_raw(std::string_view t, size_t i) {
  const auto c = static_cast<unsigned char>(t[i]);
  if (c < 0x20 || c > 0x7e || c == '\\' || c == '%') return false;
  if (c != '?' && c != '*') return true;
  if (i == 0 || i + 1 >= t.size()) return false;
  const char partner = c == '?' ? '?' : '/';
  return t[i - 1] != partner && t[i + 1] != partner;
}

}  // namespace

std::string kernel_text(std::string_view text, size_t max_bytes) {
  std::string out;
  size_t n = text.size() < max_bytes ? text.size() : max_bytes;
  out.reserve(n + 8);
  for (size_t i = 0; i < n; ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (passes_raw(text.substr(0, n), i)) out += static_cast<char>(c);
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
