// Typed values of a .fract section (see fract_params.hpp).
#include "sdfc/fract/fract_params.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace sdfc::fract {
namespace {

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool parse_hex(const std::string& w, unsigned long& out) {
  if (w.empty() || w.size() > 8) return false;
  char* end = nullptr;
  out = std::strtoul(w.c_str(), &end, 16);
  return *end == '\0';
}

}  // namespace

bool parse_number(const std::string& text, double& out) {
  if (text.empty() || text.size() > 64) return false;
  std::string t = text;
  for (char& c : t)
    if (c == ',') c = '.';  // Mandelbulber writes the saver's locale's decimal mark
  char* end = nullptr;
  out = std::strtod(t.c_str(), &end);
  return *end == '\0' && std::isfinite(out) && t.find_first_of("xXpP") == std::string::npos;
}

SourceLoc Params::loc(const std::string& key) const {
  auto it = s_.entries.find(key);
  return it != s_.entries.end() ? it->second.value_loc : s_.loc;
}

std::string Params::text(const std::string& key) const {
  auto it = s_.entries.find(key);
  if (it != s_.entries.end()) return it->second.value;
  const char* d = default_value(key, fractal_);
  if (!d) throw std::logic_error("the .fract importer reads '" + key + "' but has no default for it");
  return d;
}

double Params::number(const std::string& key) const {
  std::string t = text(key);
  double v;
  if (!parse_number(t, v)) fail(loc(key), fmt::format("'{}' expects a number, got '{}'", key, printable(t, 80)));
  return v;
}

int Params::integer(const std::string& key) const {
  double v = number(key);
  if (v != std::floor(v) || std::fabs(v) > 1e9)
    fail(loc(key), fmt::format("'{}' expects a whole number, got '{}'", key, printable(text(key), 80)));
  return int(v);
}

bool Params::boolean(const std::string& key) const {
  std::string t = text(key);
  if (t == "true" || t == "1") return true;
  if (t == "false" || t == "0") return false;
  fail(loc(key), fmt::format("'{}' expects true or false, got '{}'", key, printable(t, 80)));
}

Vec3 Params::vec3(const std::string& key) const {
  std::vector<std::string> w = words(text(key));
  Vec3 v{};
  if (w.size() != 3 || !parse_number(w[0], v[0]) || !parse_number(w[1], v[1]) || !parse_number(w[2], v[2]))
    fail(loc(key), fmt::format("'{}' expects three numbers separated by spaces, got '{}'", key,
                               printable(text(key), 80)));
  return v;
}

std::array<double, 4> Params::vec4(const std::string& key) const {
  std::vector<std::string> w = words(text(key));
  std::array<double, 4> v{};
  bool ok = w.size() == 4;
  for (size_t i = 0; ok && i < 4; ++i) ok = parse_number(w[i], v[i]);
  if (!ok)
    fail(loc(key), fmt::format("'{}' expects four numbers separated by spaces, got '{}'", key,
                               printable(text(key), 80)));
  return v;
}

Vec3 Params::colour(const std::string& key) const {
  std::vector<std::string> w = words(text(key));
  Vec3 c{};
  bool ok = w.size() == 3;
  for (size_t i = 0; ok && i < 3; ++i) {
    unsigned long h = 0;
    ok = parse_hex(w[i], h) && h <= 0xffff;
    c[i] = double(h) / 65535.0;
  }
  if (!ok)
    fail(loc(key), fmt::format("'{}' expects a colour, three 16-bit hex numbers such as 'ffff 8000 0', got '{}'",
                               key, printable(text(key), 80)));
  return c;
}

std::vector<GradientStop> Params::gradient(const std::string& key) const {
  std::vector<std::string> w = words(text(key));
  std::vector<GradientStop> out;
  bool ok = !w.empty() && w.size() % 2 == 0;
  for (size_t i = 0; ok && i + 1 < w.size(); i += 2) {
    double pos = 0;
    unsigned long rgb = 0;
    ok = parse_number(w[i], pos) && pos >= 0 && pos <= 10000 && w[i + 1].size() <= 6 && parse_hex(w[i + 1], rgb);
    out.push_back({pos / 10000.0,
                   Vec3{double((rgb >> 16) & 255) / 255.0, double((rgb >> 8) & 255) / 255.0, double(rgb & 255) / 255.0}});
  }
  if (!ok)
    fail(loc(key), fmt::format("'{}' expects a gradient, pairs of a position (0 ... 10000) and an RRGGBB colour, "
                               "got '{}'", key, printable(text(key), 80)));
  return out;
}

std::vector<std::string> Params::given_with_prefix(const std::string& prefix) const {
  std::vector<std::string> out;
  for (auto it = s_.entries.lower_bound(prefix); it != s_.entries.end() && it->first.rfind(prefix, 0) == 0; ++it)
    out.push_back(it->first);
  return out;
}

}  // namespace sdfc::fract
