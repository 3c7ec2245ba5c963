// Reading the node reference's range texts (kinds/param_range.hpp).
#include "sdfc/kinds/param_range.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "sdfc/kinds/registry.hpp"

namespace sdfc::kinds {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}
bool eat(std::string_view& s, std::string_view word) {
  if (s.substr(0, word.size()) != word) return false;
  s = trim(s.substr(word.size()));
  return true;
}
// The whole of s as a number.
std::optional<double> number(std::string_view s) {
  s = trim(s);
  double x = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return x;
}
}  // namespace

std::optional<DocRange> parse_doc_range(std::string_view text) {
  DocRange r{-kInf, kInf};
  bool read = false;
  auto lower = [&](double x, bool open) { if (x > r.lo || (x == r.lo && open)) r.lo = x, r.lo_open = open; };
  auto upper = [&](double x, bool open) { if (x < r.hi || (x == r.hi && open)) r.hi = x, r.hi_open = open; };
  while (!text.empty()) {
    const size_t cut = std::min(text.find(','), text.find(';'));
    std::string_view c = trim(text.substr(0, cut));
    text = cut == std::string_view::npos ? std::string_view{} : text.substr(cut + 1);
    eat(c, "each");
    if (c.empty()) continue;
    std::optional<double> x;
    if (c.front() == '|' && c.find("| >") != std::string_view::npos) {
      if ((x = number(c.substr(c.find("| >") + 3)))) r.abs_above = *x, read = true;
    } else if (eat(c, ">=") && (x = number(c))) {
      lower(*x, false), read = true;
    } else if (eat(c, ">") && (x = number(c))) {
      lower(*x, true), read = true;
    } else if ((eat(c, "up to") || eat(c, "at most")) && (x = number(c))) {
      upper(*x, false), read = true;
    } else if (eat(c, "less than") && (x = number(c))) {
      upper(*x, true), read = true;
    } else if (size_t to = c.find(" to "); to != std::string_view::npos) {
      auto a = number(c.substr(0, to)), b = number(c.substr(to + 4));
      if (a && b) lower(*a, false), upper(*b, false), read = true;
    }
  }
  if (!read) return std::nullopt;
  return r;
}

std::pair<double, double> slider_range(const DocRange& r, double x) {
  const double span = std::max(std::fabs(x), 1.0);
  double lo = std::max(x - span, r.lo), hi = std::min(x + span, r.hi);
  double open_lo = r.lo_open ? r.lo : -kInf, open_hi = r.hi_open ? r.hi : kInf;
  if (r.abs_above > 0 && x > r.abs_above) open_lo = std::max(open_lo, r.abs_above), lo = std::max(lo, r.abs_above);
  if (r.abs_above > 0 && x < -r.abs_above) open_hi = std::min(open_hi, -r.abs_above), hi = std::min(hi, -r.abs_above);
  // Towards an open end stop an eighth of the way short of it, never on it.
  if (lo <= open_lo) lo = open_lo + (x - open_lo) * 0.125;
  if (hi >= open_hi) hi = open_hi - (open_hi - x) * 0.125;
  return {std::min(lo, x), std::max(hi, x)};
}

const ParamDoc* documented_param(const std::vector<std::string>& steps) {
  size_t n = steps.size();
  if (n >= 3 && steps[n - 1].find_first_not_of("0123456789") == std::string::npos) --n;  // a vec3's component
  if (n < 2) return nullptr;
  const Description* d = find(steps[n - 2]);
  if (!d) return nullptr;
  for (const ParamDoc& p : d->docs)
    if (p.name == steps[n - 1] && (p.type == "number" || p.type == "vec3")) return &p;
  return nullptr;
}

}  // namespace sdfc::kinds
