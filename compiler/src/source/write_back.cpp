#include "sdfc/source/write_back.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "sdfc/source/unlock.hpp"

namespace sdfc {

namespace {

// The byte offset of a 1-based line and column in `text`, or npos.
size_t offset_of(const std::string& text, int line, int column) {
  size_t at = 0;
  for (int l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string::npos) return at;
    ++at;
  }
  return at + size_t(column - 1) <= text.size() ? at + size_t(column - 1) : std::string::npos;
}

// One word YAML reads back as the same plain scalar: no spaces, quotes,
// comment or flow characters.
bool plain_word(const std::string& s) {
  if (s.empty()) return false;
  return s.find_first_of(" \t\r\n#:,[]{}\"'&*!|>%@`") == std::string::npos;
}

struct Span {
  size_t at = 0, size = 0;
};

}  // namespace

std::string yaml_number(double x) {
  // fmt's shortest text that reads back exactly, without an exponent where
  // the plain form is as short ("40", not "4e+01").
  return fmt::format("{}", x);
}

std::string rewrite_values(const std::string& text, const SourceValue& root, const std::vector<ValueEdit>& edits) {
  std::vector<std::pair<Span, const ValueEdit*>> spans;
  for (const auto& e : edits) {
    const SourceValue* v = find_value(root, e.path);
    if (!v || !v->is_scalar() || v->loc.line <= 0)
      fail(v ? v->loc : root.loc, fmt::format("cannot write {}: the scene has no single value at this path", e.path));
    if (!plain_word(e.text)) fail(v->loc, fmt::format("cannot write {}: '{}' is not one plain value", e.path, e.text));
    size_t at = offset_of(text, v->loc.line, v->loc.column);
    // A quoted value keeps its quotes; only the characters between them change.
    const bool quoted = at < text.size() && (text[at] == '"' || text[at] == '\'');
    if (quoted) ++at;
    if (at == std::string::npos || text.compare(at, v->scalar.size(), v->scalar) != 0 ||
        (quoted && (at + v->scalar.size() >= text.size() || text[at + v->scalar.size()] != text[at - 1])))
      fail(v->loc, fmt::format("cannot write {}: its text in the file is not one plain value", e.path),
           "write values that span lines or use escapes by hand");
    spans.push_back({{at, v->scalar.size()}, &e});
  }
  std::sort(spans.begin(), spans.end(), [](const auto& a, const auto& b) { return a.first.at < b.first.at; });
  std::string out;
  size_t from = 0;
  for (const auto& [s, e] : spans) {
    if (s.at < from) fail(root.loc, fmt::format("cannot write {}: it is edited twice", e->path));
    out.append(text, from, s.at - from);
    out += e->text;
    from = s.at + s.size;
  }
  out.append(text, from, std::string::npos);
  return out;
}

bool save_if_unchanged(const std::string& path, const std::string& loaded, const std::string& text) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream now;
  now << in.rdbuf();
  if (!in || now.str() != loaded) return false;
  // The real file, so a symlinked scene stays a symlink.
  char real[PATH_MAX];
  const std::string target = ::realpath(path.c_str(), real) ? std::string(real) : path;
  std::string temp = target + ".XXXXXX";
  int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(SourceLoc(std::make_shared<const std::string>(path), 0, 0), "cannot create a temporary file beside the scene");
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) ::fchmod(fd, st.st_mode & 07777);  // mkstemp makes it private
  size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) break;
    done += size_t(n);
  }
  const bool ok = done == text.size() && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok || ::rename(temp.c_str(), target.c_str()) != 0) {
    ::unlink(temp.c_str());
    fail(SourceLoc(std::make_shared<const std::string>(path), 0, 0), "cannot write the scene file");
  }
  return true;
}

}  // namespace sdfc
