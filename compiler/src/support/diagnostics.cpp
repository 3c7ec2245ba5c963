#include "sdfc/support/diagnostics.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sdfc {

std::string SourceLoc::str() const {
  std::string s = file ? *file : std::string("<scene>");
  if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
  return s;
}

std::string printable(std::string_view text, size_t max_bytes) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  size_t n = std::min(text.size(), max_bytes);
  for (size_t i = 0; i < n; ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    // C0 controls, DEL and the UTF-8 spelling of the C1 controls (U+0080..U+009F).
    bool c1 = c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
              static_cast<unsigned char>(text[i + 1]) <= 0x9f;
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f || c1) {
      unsigned char q = c1 ? static_cast<unsigned char>(text[++i]) : c;
      out += "\\x";
      out += kHex[q >> 4];
      out += kHex[q & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (n < text.size()) out += fmt::format("... ({} bytes more)", text.size() - n);
  return out;
}

std::string Diagnostic::str() const {
  std::string s = loc.str() + ": error: " + message;
  if (!hint.empty()) s += " (" + hint + ")";
  return printable(s);
}

static std::string join(const std::vector<Diagnostic>& d) {
  std::string s;
  for (const auto& x : d) {
    if (!s.empty()) s += "\n";
    s += x.str();
  }
  return s;
}

SceneError::SceneError(std::vector<Diagnostic> diags) : std::runtime_error(join(diags)), diags_(std::move(diags)) {}

void fail(const SourceLoc& loc, std::string message, std::string hint) {
  throw SceneError(Diagnostic(loc, std::move(message), std::move(hint)));
}

void DiagnosticSink::error(const SourceLoc& loc, std::string message, std::string hint) {
  diags_.push_back({loc, std::move(message), std::move(hint)});
}

void DiagnosticSink::throw_if_any() const {
  if (!diags_.empty()) throw SceneError(diags_);
}

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of neighbours each cost one ("boen" is one step from "bone").
size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string_view best;
  size_t best_d = SIZE_MAX;
  for (auto c : candidates) {
    size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  // Allow about one typo per three letters; further off is not a suggestion.
  size_t limit = std::max<size_t>(1, std::max(word.size(), best.size()) / 3);
  if (best.empty() || best_d > limit) return {};
  return "did you mean '" + std::string(best) + "'?";
}

}  // namespace sdfc
