#include "sdfc/codegen/stdlib_manifest.hpp"

#include <functional>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

#include "sdfc/stdlib_files.hpp"

namespace sdfc::codegen {

namespace {

std::string trim(std::string s) {
  size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

}  // namespace

const StdlibManifest& StdlibManifest::instance() {
  static const StdlibManifest m = [] {
    StdlibManifest out;
    for (const auto& file : stdlib_files()) {
      std::istringstream in{std::string(file.text)};
      std::string line;
      StdlibFunction* cur = nullptr;
      while (std::getline(in, line)) {
        if (starts_with(line, "//! fn ")) {
          out.fns_.push_back({});
          cur = &out.fns_.back();
          cur->name = trim(line.substr(7));
          cur->file = std::string(file.name);
        } else if (cur && starts_with(line, "//! deps:")) {
          std::istringstream deps(line.substr(9));
          std::string d;
          while (std::getline(deps, d, ','))
            if (!trim(d).empty()) cur->deps.push_back(trim(d));
        } else if (cur && starts_with(line, "//! class:")) {
          cur->cls = trim(line.substr(10));
        } else if (cur && trim(line) == "//! after-scene") {
          cur->after_scene = true;
        }
        if (cur) cur->text += line + "\n";
      }
    }
    for (auto& f : out.fns_)
      while (f.text.size() >= 2 && f.text[f.text.size() - 2] == '\n') f.text.pop_back();  // one trailing newline
    return out;
  }();
  return m;
}

const StdlibFunction* StdlibManifest::find(std::string_view name) const {
  for (const auto& f : fns_)
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<const StdlibFunction*> StdlibManifest::closure(const std::vector<std::string>& roots) const {
  std::vector<const StdlibFunction*> order;
  std::unordered_set<std::string> seen;
  std::function<void(const std::string&)> visit = [&](const std::string& name) {
    if (!seen.insert(name).second) return;
    const StdlibFunction* f = find(name);
    if (!f) throw std::logic_error("stdlib has no function '" + name + "'");
    for (const auto& d : f->deps) visit(d);
    order.push_back(f);
  };
  for (const auto& r : roots) visit(r);
  return order;
}

}  // namespace sdfc::codegen
