#pragma once
// Source locations and the errors a user sees: `file:line:col: error: ...`.
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sdfc {

struct SourceLoc {
  SourceLoc() = default;
  SourceLoc(std::shared_ptr<const std::string> f, int l, int c) : file(std::move(f)), line(l), column(c) {}

  std::shared_ptr<const std::string> file;  // shared: every value of a file points at one name
  int line = 0;                             // 1-based; 0 = unknown
  int column = 0;                           // 1-based

  std::string str() const;  // "file:line:col" (or just "file" when unknown)
};

struct Diagnostic {
  Diagnostic() = default;
  Diagnostic(SourceLoc l, std::string m, std::string h = {}) : loc(std::move(l)), message(std::move(m)), hint(std::move(h)) {}

  SourceLoc loc;
  std::string message;
  std::string hint;  // e.g. "did you mean 'sphere'?"; may be empty

  std::string str() const;
};

// A scene error: one or more diagnostics. The CLI maps it to exit code 1.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(std::vector<Diagnostic> diags);
  explicit SceneError(Diagnostic d) : SceneError(std::vector<Diagnostic>{std::move(d)}) {}
  const std::vector<Diagnostic>& diagnostics() const { return diags_; }

 private:
  std::vector<Diagnostic> diags_;
};

// `text` safe to print on a terminal: control characters (ESC, CR, BEL, the
// C1 controls...) shown as \x1b, at most `max_bytes` of it. Every message
// that can hold text from a scene, a file name or the environment goes
// through it.
std::string printable(std::string_view text, size_t max_bytes = 2000);

// Throws a SceneError with one diagnostic.
[[noreturn]] void fail(const SourceLoc& loc, std::string message, std::string hint = {});

// Collects diagnostics so one run reports every independent mistake.
class DiagnosticSink {
 public:
  void error(const SourceLoc& loc, std::string message, std::string hint = {});
  bool empty() const { return diags_.empty(); }
  // Throws SceneError when anything was reported.
  void throw_if_any() const;

 private:
  std::vector<Diagnostic> diags_;
};

// "did you mean 'x'?" for the closest candidate within a small edit distance.
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates);
size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace sdfc
