// YAML text helpers for the importer (see yaml_text.hpp).
#include "yaml_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::fract {

std::string num(double v) {
  if (v == 0) return "0";
  for (int digits = 6; digits <= 17; ++digits) {
    std::string s = fmt::format("{:.{}g}", v, digits);
    if (std::strtod(s.c_str(), nullptr) == v) return s;
  }
  return fmt::format("{:.17g}", v);
}

std::string vec(const Vec3& v) { return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]"; }

std::string vec(const std::vector<double>& v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v[i]);
  return s + "]";
}

std::string commented(const std::string& text, const std::string& from) {
  if (from.empty()) return text + "\n";
  std::string t = text;
  if (t.size() < 48) t.resize(48, ' ');
  // Keys come from the importer's own tables, never from the file, but
  // printable() keeps any control character out all the same.
  return t + "  # " + printable(from, 200) + "\n";
}

void write_node(std::string& out, const Node& node, int indent, bool item) {
  std::string pad(size_t(indent), ' ');
  std::string lead = item ? pad.substr(0, pad.size() - 2) + "- " : pad;
  if (node.children.empty() && node.fields.empty()) {
    out += commented(lead + node.kind + ": {}", node.from);
  } else {
    out += commented(lead + node.kind + ":", node.from);
    for (const Node& c : node.children) write_node(out, c, indent + 4, true);
    for (const Field& f : node.fields) out += commented(pad + "  " + f.key + ": " + f.value, f.from);
  }
  for (const Field& f : node.modifiers) out += commented(pad + f.key + ": " + f.value, f.from);
}

}  // namespace sdfc::fract
