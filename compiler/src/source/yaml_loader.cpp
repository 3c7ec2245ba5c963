#include "sdfc/source/yaml_loader.hpp"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/exceptions.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "yaml_events.hpp"

namespace sdfc {

namespace {

// Deeper than any sensible scene; stops a hostile file from exhausting the stack.
constexpr int kMaxDepth = 200;
constexpr const char* kFlattenHint = "flatten it: a union takes any number of children";
// Aliases are copied where they are used, so a few lines of nested aliases
// ("billion laughs") could expand to billions of values. A scene at the
// kernel size limit (4096 node evaluations) holds far fewer.
constexpr size_t kMaxValues = 200'000;

// Caps on what is read at all: a scene file (the largest example is 4 KB,
// 10 000 spheres take 600 KB) and one value (a name, an expression).
constexpr std::uintmax_t kMaxFileBytes = 8u << 20;
constexpr size_t kMaxScalarBytes = 64u << 10;

struct Budget {
  size_t values = 0;
  bool anchors = false;  // the text defines anchors (&name), so aliases may be what grew it
};

SourceLoc loc_of(const YAML::Mark& m, const std::shared_ptr<const std::string>& file) {
  return {file, m.line >= 0 ? m.line + 1 : 0, m.column >= 0 ? m.column + 1 : 0};
}

bool tag_is_quoted(const yaml_events::Document& doc, const yaml_events::Value& n) { return doc.tags[n.tag] == "!"; }

SourceValue convert(const yaml_events::Document& doc, std::uint32_t id, const std::shared_ptr<const std::string>& file,
                    int depth, Budget& budget) {
  using Kind = yaml_events::Value::Kind;
  const yaml_events::Value& n = doc.values[id];
  SourceValue v;
  v.loc = loc_of(n.mark, file);
  if (depth > kMaxDepth)
    fail(v.loc, fmt::format("the scene nests deeper than {} levels", kMaxDepth), kFlattenHint);
  if (++budget.values > kMaxValues)
    fail(v.loc,
         budget.anchors ? fmt::format("the scene has more than {} values once its aliases (*name) are expanded", kMaxValues)
                        : fmt::format("the scene has more than {} values", kMaxValues),
         budget.anchors ? "use fewer or less deeply nested aliases" : "no scene needs that many; use fewer values");
  // yaml-cpp reports "?" for a plain scalar and "!" for a quoted one; any
  // other tag (!foo, !!binary) means something this format does not have.
  if (const std::string& tag = doc.tags[n.tag]; !tag.empty() && tag != "?" && tag != "!" &&
                                         tag.rfind("tag:yaml.org,2002:", 0) != 0)
    fail(v.loc, fmt::format("unknown tag '{}'", tag.substr(0, 80)), "scene values take no tags; remove it");
  const std::uint32_t* kids = doc.kids.data() + n.first;
  switch (n.kind) {
    case Kind::Null: v.kind = SourceValue::Kind::Null; break;
    case Kind::Scalar:
      v.kind = SourceValue::Kind::Scalar;
      if (n.scalar.size() > kMaxScalarBytes)
        fail(v.loc, fmt::format("a value of {} bytes; at most {} are allowed", n.scalar.size(), kMaxScalarBytes));
      v.scalar = n.scalar;
      v.quoted = tag_is_quoted(doc, n);
      break;
    case Kind::Sequence:
      v.kind = SourceValue::Kind::Sequence;
      v.items.reserve(n.count);
      for (std::uint32_t i = 0; i < n.count; ++i) v.items.push_back(convert(doc, kids[i], file, depth + 1, budget));
      break;
    case Kind::Map:
      v.kind = SourceValue::Kind::Map;
      v.entries.reserve(n.count / 2);
      for (std::uint32_t i = 0; i + 1 < n.count; i += 2) {
        SourceValue key = convert(doc, kids[i], file, depth + 1, budget);
        if (!key.is_scalar())
          fail(key.loc, "a map key must be a plain word, not " + key.kind_name(), "");
        if (v.find(key.scalar))
          fail(key.loc, "duplicate key '" + key.scalar + "'", "each key may appear once in a map");
        SourceValue value = convert(doc, kids[i + 1], file, depth + 1, budget);
        // An empty value ("scene:" then nothing) is marked where the next
        // token starts, often a later line; point just past its key instead.
        if (value.is_null() && value.loc.line != key.loc.line)
          value.loc = SourceLoc(file, key.loc.line, key.loc.column + int(key.scalar.size()));
        v.entries.emplace_back(std::move(key), std::move(value));
      }
      break;
  }
  return v;
}

// yaml-cpp marks its depth error at the end of the file. In flow style
// ("{union: [{union: [...") point at the bracket that passes our limit
// instead; returns false when the nesting is not in brackets.
bool deepest_flow_bracket(const std::string& text, int limit, int& line, int& col) {
  int depth = 0;
  char quote = 0;
  line = 1, col = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line, col = 0;
      continue;
    }
    ++col;
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\t')) {
      i = std::min(text.find('\n', i), text.size()) - 1;  // a comment: skip to the line end
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return false;
}

}  // namespace


// The line of a "---" marker that starts a second document, or 0.
static int second_document_line(const std::string& text) {
  bool content = false;
  int line = 1;
  for (size_t i = 0; i < text.size(); ++line) {
    size_t end = std::min(text.find('\n', i), text.size());
    std::string_view l(text.data() + i, end - i);
    const bool marker = l.substr(0, 3) == "---" && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
    if (marker && content) return line;
    const size_t first = l.find_first_not_of(" \t\r");
    if (!marker && first != std::string_view::npos && l[first] != '#') content = true;
    i = end + 1;
  }
  return 0;
}

SourceValue load_yaml_text(const std::string& text, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  // yaml-cpp accepts some binary input silently; reject it with a clear message.
  for (size_t i = 0; i < text.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == 0 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t')) {
      int line = 1, col = 1;
      for (size_t j = 0; j < i; ++j) text[j] == '\n' ? (++line, col = 1) : ++col;
      fail(SourceLoc(file, line, col), fmt::format("this is not a text file (control byte 0x{:02x})", c), "a scene is a YAML text file");
    }
  }
  // YAML forbids tabs in indentation; yaml-cpp reports them late and vaguely,
  // so point at the first one ourselves.
  for (size_t i = 0, line = 1; i < text.size(); ++line) {
    size_t end = text.find('\n', i);
    if (end == std::string::npos) end = text.size();
    size_t first = text.find_first_not_of(' ', i);
    if (first < end && text[first] == '\t')
      fail(SourceLoc(file, int(line), int(first - i + 1)), "a tab in the indentation", "YAML indents with spaces only; use spaces");
    i = end + 1;
  }
  yaml_events::Document doc;
  try {
    // yaml-cpp's LoadAll loops for minutes on some junk (", x"), so the
    // second document is found by its marker: a line starting "---" after
    // any content (YAML forbids it inside a scalar).
    if (int line = second_document_line(text)) {
      fail(SourceLoc(file, line, 1), "a second YAML document (after '---'); a scene file holds one",
           "remove the '---' line or split the file");
    }
    doc = yaml_events::parse(text);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own guard (deeper than ours, so the same message fits).
    SourceLoc at = loc_of(e.mark, file);
    if (int line = 0, col = 0; deepest_flow_bracket(text, kMaxDepth, line, col)) at = SourceLoc(file, line, col);
    fail(at, fmt::format("the scene nests deeper than {} levels", kMaxDepth), kFlattenHint);
  } catch (const YAML::Exception& e) {
    fail(loc_of(e.mark, file), "YAML syntax error: " + e.msg);
  }
  if (doc.root < 0 || doc.values[size_t(doc.root)].kind == yaml_events::Value::Kind::Null)
    fail(SourceLoc(file, 1, 1), "the scene file is empty", "a scene needs at least a 'scene:' key");
  Budget budget;
  budget.anchors = text.find('&') != std::string::npos;
  return convert(doc, std::uint32_t(doc.root), file, 0, budget);
}

SourceValue load_yaml_file(const std::string& path) {
  auto file = std::make_shared<const std::string>(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    fail(SourceLoc(file, 0, 0), "no such file", "");
  if (std::filesystem::is_directory(path, ec))
    fail(SourceLoc(file, 0, 0), "this is a directory, not a scene file", "");
  // A device (/dev/zero), a FIFO or a socket could be endless: read files only.
  if (!std::filesystem::is_regular_file(path, ec))
    fail(SourceLoc(file, 0, 0), "this is not a regular file (a device, pipe or socket)", "a scene is a YAML text file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxFileBytes)
    fail(SourceLoc(file, 0, 0), fmt::format("the file is {} bytes; scene files are limited to {}", size, kMaxFileBytes),
         "a scene this large is not a scene (10 000 shapes take 600 KB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(SourceLoc(file, 0, 0), "cannot read the file (permission denied?)", "");
  std::string text(std::min<std::uintmax_t>(size, kMaxFileBytes) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) fail(SourceLoc(file, 0, 0), "error while reading the file", "");
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > kMaxFileBytes) fail(SourceLoc(file, 0, 0), "the file grew past the size limit while it was read");
  return load_yaml_text(text, path);
}

}  // namespace sdfc
