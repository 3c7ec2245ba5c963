// The .fract text format (Mandelbulber's settings.cpp): `# ` comment lines
// (the header, `# version X.YZ`, `# only modified parameters`), `[section]`
// lines, `key value;` lines, and in [frames]/[keyframes] `;`-separated rows
// under a `frame;...` header (plus an optional `interpolation;...` row).
#include <fmt/format.h>

#include <fstream>
#include <memory>
#include <sstream>

#include "fract_internal.hpp"
#include "sdfc/fract/fract_file.hpp"

namespace sdfc::fract {
namespace {

// A settings file is small; this bounds what a hostile one can make us hold.
constexpr size_t kMaxFileBytes = 64u << 20;

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  size_t i = 0;
  for (;;) {
    size_t j = s.find(sep, i);
    out.push_back(s.substr(i, j == std::string::npos ? std::string::npos : j - i));
    if (j == std::string::npos) return out;
    i = j + 1;
  }
}

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

class Parser {
 public:
  Parser(const std::string& text, const std::string& name)
      : text_(text), file_name_(std::make_shared<const std::string>(name)) {
    out_.name = name;
  }

  File run() {
    std::istringstream in(text_);
    std::string raw;
    int line = 0;
    while (std::getline(in, raw)) {
      ++line;
      if (!raw.empty() && raw.back() == '\r') raw.pop_back();
      handle(raw, line);
    }
    if (line == 0 || !saw_header_) fail(loc(1, 1), "not a Mandelbulber settings file: the first line must be '" +
                                                       std::string(kHeader) + "'");
    if (!out_.main.present) fail(loc(line, 1), "the file has no [main_parameters] section");
    sink_.throw_if_any();
    return std::move(out_);
  }

 private:
  SourceLoc loc(int line, int col) const { return SourceLoc(file_name_, line, col); }

  void handle(const std::string& raw, int line) {
    if (line == 1) {
      if (raw.rfind(kHeader, 0) != 0) {
        if (raw.rfind("Mandelbulber 1.", 0) == 0)
          fail(loc(1, 1), "this is a Mandelbulber 1.x settings file; only files of Mandelbulber 2 can be imported",
               "open it in Mandelbulber 2 and save it again");
        fail(loc(1, 1), "not a Mandelbulber settings file: the first line must be '" + std::string(kHeader) + "'");
      }
      saw_header_ = true;
      return;
    }
    std::string s = trim(raw);
    if (section_ == "description") {  // free text up to the next section
      if (!(s.size() > 2 && s.front() == '[' && s.back() == ']')) return;
    }
    if (s.empty()) return;
    if (s[0] == '#') {
      if (s.rfind("# version", 0) == 0) version(s, line, int(raw.find('#')) + 1);
      if (s.find("only modified parameters") != std::string::npos) out_.only_modified = true;
      return;
    }
    if (s.front() == '[') return open_section(s, line, int(raw.find('[')) + 1);
    if (section_.empty()) {
      sink_.error(loc(line, 1), "a line before the first [section]", "settings start with [main_parameters]");
      return;
    }
    if (table_) return table_row(raw, line);
    key_value(raw, line);
  }

  void version(const std::string& s, int line, int col) {
    std::string v = trim(s.substr(9));
    for (char& c : v)
      if (c == ',') c = '.';
    char* end = nullptr;
    double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !(d > 0 && d < 100)) {
      sink_.error(loc(line, col), fmt::format("expected a version number after '# version', got '{}'", printable(v)));
      return;
    }
    out_.version = d;
    out_.version_loc = loc(line, col);
  }

  void open_section(const std::string& s, int line, int col) {
    if (s.back() != ']') {
      sink_.error(loc(line, col), "expected ']' at the end of the section name");
      return;
    }
    section_ = s.substr(1, s.size() - 2);
    table_ = nullptr;
    current_ = nullptr;
    if (section_ == "main_parameters") current_ = &out_.main;
    else if (section_.rfind("fractal_", 0) == 0 && section_.size() == 9 && section_[8] >= '1' && section_[8] <= '9')
      current_ = &out_.fractal[size_t(section_[8] - '1')];
    else if (section_ == "frames") table_ = &out_.frames;
    else if (section_ == "keyframes") table_ = &out_.keyframes;
    else if (section_ != "description") {
      sink_.error(loc(line, col + 1), fmt::format("unknown section [{}]", printable(section_)),
                  "Mandelbulber writes [main_parameters], [fractal_1] ... [fractal_9], [frames], [keyframes]");
      section_ = "description";  // skip its lines
      return;
    }
    if (current_) {
      current_->present = true;
      current_->loc = loc(line, col);
    }
    if (table_) {
      table_->present = true;
      table_->loc = loc(line, col);
    }
  }

  void key_value(const std::string& raw, int line) {
    size_t b = raw.find_first_not_of(" \t");
    size_t sp = raw.find(' ', b);
    size_t semi = raw.rfind(';');
    if (sp == std::string::npos || semi == std::string::npos || semi < sp) {
      int col = int((semi == std::string::npos ? raw.size() : semi) + 1);
      sink_.error(loc(line, col), fmt::format("expected 'name value;', got '{}'", printable(trim(raw), 80)),
                  sp == std::string::npos ? "a value must follow the name, separated by a space"
                                          : "each line ends with ';'");
      return;
    }
    std::string key = raw.substr(b, sp - b);
    std::string value = trim(raw.substr(sp + 1, semi - sp - 1));
    apply_renames(key, value, out_.version);
    Entry e{value, loc(line, int(b) + 1), loc(line, int(raw.find_first_not_of(' ', sp)) + 1)};
    if (!current_->entries.emplace(key, e).second)
      sink_.error(e.loc, fmt::format("'{}' is given twice in [{}]", printable(key), printable(section_)));
  }

  void table_row(const std::string& raw, int line) {
    std::vector<std::string> cells = split(trim(raw), ';');
    if (table_->columns.empty()) {
      if (cells[0] != "frame") {
        sink_.error(loc(line, 1), fmt::format("the first line of [{}] names its columns: expected 'frame;...'",
                                              section_));
        table_->columns.push_back("frame");
        return;
      }
      table_->columns = cells;
      return;
    }
    if (cells[0] == "interpolation") return;  // how Mandelbulber interpolates each column; sdfc picks its own
    if (cells.size() != table_->columns.size()) {
      sink_.error(loc(line, 1), fmt::format("this row of [{}] has {} values, its header names {} columns", section_,
                                            cells.size(), table_->columns.size()));
      return;
    }
    table_->rows.push_back(std::move(cells));
    table_->row_locs.push_back(loc(line, 1));
  }

  const std::string& text_;
  std::shared_ptr<const std::string> file_name_;
  File out_;
  DiagnosticSink sink_;
  std::string section_;
  Section* current_ = nullptr;
  Table* table_ = nullptr;
  bool saw_header_ = false;
};

}  // namespace

File parse_text(const std::string& text, const std::string& name) {
  if (text.find('\0') != std::string::npos)
    fail(SourceLoc(std::make_shared<const std::string>(name), 1, 1), "not a text file (it holds NUL bytes)");
  return Parser(text, name).run();
}

File read_file(const std::string& path) {
  auto name = std::make_shared<const std::string>(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(SourceLoc(name, 0, 0), "cannot open the file");
  std::string text;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, size_t(in.gcount()));
    if (text.size() > kMaxFileBytes) fail(SourceLoc(name, 0, 0), "the file is larger than 64 MB");
  }
  if (in.bad()) fail(SourceLoc(name, 0, 0), "cannot read the file (is it a directory?)");
  return parse_text(text, path);
}

bool is_fract_path(const std::string& path) {
  if (path.size() > 6 && path.compare(path.size() - 6, 6, ".fract") == 0) return true;
  std::ifstream in(path, std::ios::binary);
  char buf[28] = {};
  in.read(buf, sizeof buf);
  return in.gcount() == 28 && std::string(buf, 28) == kHeader;
}

}  // namespace sdfc::fract
