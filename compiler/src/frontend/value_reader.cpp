#include "sdfc/frontend/value_reader.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace sdfc::frontend {

namespace {

std::string range_text(const Range& r) {
  if (r.lo == 0 && r.lo_open) return r.hi >= kMaxMagnitude ? "a positive number" : fmt::format("a positive number up to {}", r.hi);
  if (r.lo == 0) return r.hi >= kMaxMagnitude ? "a number >= 0" : fmt::format("a number from 0 to {}", r.hi);
  return fmt::format("a number from {} to {}", r.lo, r.hi);
}

bool in_range(double x, const Range& r) { return !(r.lo_open ? x <= r.lo : x < r.lo) && x <= r.hi; }

double fallback(const Range& r) { return r.lo_open ? r.lo + 1 : std::max(r.lo, std::min(r.hi, 1.0)); }

}  // namespace

Param Param::scaled(double k) const {
  Param p;
  p.value = value * k;
  p.lo = std::min(lo * k, hi * k);
  p.hi = std::max(lo * k, hi * k);
  if (anim) p.anim = expr::binary(expr::Op::Mul, expr::number(k), anim);
  return p;
}

expr::ExprPtr ValueReader::expression(const SourceValue& v, bool* plain) {
  *plain = !v.is_scalar() || !v.quoted || !expr::looks_like_expression(v.scalar) || v.scalar.empty();
  if (*plain) return nullptr;
  try {
    SourceLoc at = v.loc;
    at.column += 1;  // a quoted string's location is its opening quote
    return expr::fold(expr::parse(v.scalar, at, {"time"}));
  } catch (const SceneError& err) {
    for (const auto& d : err.diagnostics()) sink_.error(d.loc, d.message, d.hint);
    return nullptr;
  }
}

Param ValueReader::param(const SourceValue& v, std::string_view what, Range r) {
  if (v.unlock && v.is_scalar() && !v.quoted) return unlocked(v, what, r);
  bool plain = true;
  expr::ExprPtr e = expression(v, &plain);
  if (plain) return number(v, what, r);
  if (!e) return fallback(r);
  if (!expr::uses(e, "time")) {
    double x = expr::evaluate(e, {});
    if (!std::isfinite(x) || std::fabs(x) > kMaxMagnitude) {
      sink_.error(v.loc, fmt::format("{}: \"{}\" is {}, too large (the limit is {:g})", what, v.scalar, x, kMaxMagnitude), "");
      return fallback(r);
    }
    if (!in_range(x, r)) {
      sink_.error(v.loc, fmt::format("{}: \"{}\" is {}; expected {}", what, v.scalar, x, range_text(r)), "");
      return fallback(r);
    }
    return x;
  }
  Param p;
  p.anim = e;
  expr::Interval span = expr::evaluate_interval(e, {{"time", {0, expr::kMaxTime}}});
  p.value = expr::evaluate(e, {{"time", 0.0}});
  p.lo = span.lo, p.hi = span.hi;
  if (!std::isfinite(p.lo) || !std::isfinite(p.hi) || !std::isfinite(p.value)) {
    sink_.error(v.loc, fmt::format("{}: \"{}\" is not finite for every time from 0 on", what, v.scalar),
                "keep an animated value bounded, e.g. \"1 + 0.5*sin(time)\"");
    return fallback(r);
  }
  if (!in_range(p.lo, r) || !in_range(p.hi, r)) {
    sink_.error(v.loc, fmt::format("{}: \"{}\" ranges over [{:g}, {:g}] as time goes on; expected {} at every time",
                                   what, v.scalar, p.lo, p.hi, range_text(r)),
                "the range is estimated by interval arithmetic over time 0 ... 1e6 s");
    return fallback(r);
  }
  return p;
}

Param3 ValueReader::param3(const SourceValue& v, std::string_view what, Range r) {
  Param3 out{fallback(r), fallback(r), fallback(r)};
  if (!v.is_seq() || v.items.size() != 3) {
    sink_.error(v.loc, fmt::format("{}: expected a list of 3 numbers [x, y, z], got {}", what, v.kind_name()), "");
    return out;
  }
  for (size_t i = 0; i < 3; ++i) out[i] = param(v.items[i], what, r);
  return out;
}

double ValueReader::number(const SourceValue& v, std::string_view what, Range r) {
  bool plain = true;
  if (expr::ExprPtr e = expression(v, &plain); !plain) {
    if (!e) return fallback(r);
    if (expr::uses(e, "time")) {
      sink_.error(v.loc, fmt::format("{} cannot be animated", what),
                  "only the values listed under 'Animation' in docs/scene-format.md may use time");
      return fallback(r);
    }
    return param(v, what, r).value;
  }
  if (!v.is_scalar() || v.quoted) {
    std::string hint;
    if (v.quoted) {
      // A quoted number is a slip; a formula is a feature this value lacks.
      char* end = nullptr;
      std::strtod(v.scalar.c_str(), &end);
      const bool number = !v.scalar.empty() && end == v.scalar.c_str() + v.scalar.size();
      hint = number ? "remove the quotes"
                    : "this value takes a plain number; only the values listed under 'Animation' in docs/scene-format.md may be expressions";
    }
    sink_.error(v.loc, fmt::format("{}: expected a number, got {}", what, v.kind_name()), hint);
    return r.lo_open ? r.lo + 1 : std::max(r.lo, std::min(r.hi, 1.0));
  }
  const std::string& s = v.scalar;
  // YAML spells infinity and NaN as .inf/.nan; strtod knows inf/nan. Both are refused.
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos) {
    sink_.error(v.loc, fmt::format("{}: {} is not a finite number", what, s), "");
    return 1;
  }
  errno = 0;
  char* end = nullptr;
  double x = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) {
    sink_.error(v.loc, fmt::format("{}: expected a number, got '{}'", what, s), "");
    return 1;
  }
  if (errno == ERANGE && std::fabs(x) < 1) {  // underflow: 1e-320
    sink_.error(v.loc, fmt::format("{}: {} is too close to zero for a number sdfc can use", what, s),
                "write 0, or a number of at least 1e-300");
    return 1;
  }
  if (errno == ERANGE || !std::isfinite(x) || std::fabs(x) > kMaxMagnitude) {
    sink_.error(v.loc, fmt::format("{}: {} is too large (the limit is {:g})", what, s, kMaxMagnitude), "");
    return 1;
  }
  bool below = r.lo_open ? x <= r.lo : x < r.lo;
  if (below || x > r.hi) {
    sink_.error(v.loc, fmt::format("{}: expected {}, got {}", what, range_text(r), s), "");
    return r.lo_open ? r.lo + 1 : std::max(r.lo, std::min(r.hi, 1.0));
  }
  return x;
}

int ValueReader::integer(const SourceValue& v, std::string_view what, int lo, int hi) {
  bool plain = true;
  if (expr::ExprPtr e = expression(v, &plain); !plain) {
    if (e && expr::uses(e, "time"))
      sink_.error(v.loc, fmt::format("{} cannot be animated", what),
                  "a whole number shapes the kernel's code (a loop count, a choice); it is fixed when the scene compiles");
    else if (e) {
      // A static expression folds to its value, which must be a whole number in range.
      double x = expr::evaluate(e, {});
      if (x == std::floor(x) && x >= lo && x <= hi) return static_cast<int>(x);
      sink_.error(v.loc, fmt::format("{}: expected a whole number from {} to {}, but \"{}\" is {}", what, lo, hi, v.scalar, x), "");
    }
    return lo;
  }
  if (!v.is_scalar() || v.quoted || v.scalar.find_first_not_of("+-0123456789") != std::string::npos ||
      v.scalar.empty()) {
    sink_.error(v.loc, fmt::format("{}: expected a whole number, got {}", what, v.kind_name()), "");
    return lo;
  }
  errno = 0;
  char* end = nullptr;
  long long x = std::strtoll(v.scalar.c_str(), &end, 10);
  // strtoll stops at the first character it cannot use: "5-5" is not a number.
  if (end != v.scalar.c_str() + v.scalar.size()) {
    sink_.error(v.loc, fmt::format("{}: expected a whole number, got '{}'", what, v.scalar), "");
    return lo;
  }
  if (errno == ERANGE || x < lo || x > hi) {
    sink_.error(v.loc, fmt::format("{}: expected a whole number from {} to {}, got {}", what, lo, hi, v.scalar), "");
    return lo;
  }
  return static_cast<int>(x);
}

std::vector<double> ValueReader::vecn(const SourceValue& v, std::string_view what, size_t n, Range r) {
  std::vector<double> out(n, r.lo_open ? r.lo + 1 : std::max(r.lo, std::min(r.hi, 0.0)));
  if (!v.is_seq() || v.items.size() != n) {
    std::string example = n == 3 ? "[x, y, z]" : n == 4 ? "[a, b, c, d]" : "a list";
    sink_.error(v.loc, fmt::format("{}: expected a list of {} numbers {}, got {}", what, n, example, v.kind_name()), "");
    return out;
  }
  for (size_t i = 0; i < n; ++i) out[i] = number(v.items[i], what, r);
  return out;
}

Vec3d ValueReader::vec3(const SourceValue& v, std::string_view what, Range r) {
  auto x = vecn(v, what, 3, r);
  return {x[0], x[1], x[2]};
}

Vec3d ValueReader::direction(const SourceValue& v, std::string_view what) {
  Vec3d d = vec3(v, what);
  double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (len < 1e-9) {
    if (v.is_seq() && v.items.size() == 3)
      sink_.error(v.loc, fmt::format("{}: a direction must not have zero length", what), "");
    return {0, 0, 1};
  }
  return {d[0] / len, d[1] / len, d[2] / len};
}

std::string ValueReader::word(const SourceValue& v, std::string_view what, std::initializer_list<std::string_view> choices) {
  std::vector<std::string_view> list(choices);
  std::string all;
  for (auto c : list) all += (all.empty() ? "" : ", ") + std::string(c);
  if (!v.is_scalar()) {
    sink_.error(v.loc, fmt::format("{}: expected one of {}, got {}", what, all, v.kind_name()), "");
    return std::string(list.front());
  }
  for (auto c : list)
    if (v.scalar == c) return v.scalar;
  sink_.error(v.loc, fmt::format("{}: expected one of {}, got '{}'", what, all, v.scalar), did_you_mean(v.scalar, list));
  return std::string(list.front());
}

MapReader::MapReader(ValueReader& r, const SourceValue& v, std::string_view what,
                     std::initializer_list<std::string_view> allowed)
    : MapReader(r, v, what, std::vector<std::string_view>(allowed)) {}

MapReader::MapReader(ValueReader& r, const SourceValue& v, std::string_view what,
                     const std::vector<std::string_view>& allowed)
    : r_(r), v_(v), what_(what) {
  if (!v.is_map()) {
    r_.sink().error(v.loc, fmt::format("{}: expected a map of settings, got {}", what, v.kind_name()), "");
    ok_ = false;
    return;
  }
  const std::vector<std::string_view>& keys = allowed;
  for (const auto& [k, val] : v.entries) {
    bool known = false;
    for (auto a : keys) known = known || k.scalar == a;
    if (!known) {
      std::string all;
      for (auto a : keys) all += (all.empty() ? "" : ", ") + std::string(a);
      std::string hint = did_you_mean(k.scalar, keys);
      if (hint.empty()) hint = "allowed: " + all;
      r_.sink().error(k.loc, fmt::format("unknown key '{}' in {}", k.scalar, what), hint);
    }
  }
}

std::string MapReader::path(std::string_view key) const { return what_ + "." + std::string(key); }

const SourceValue* MapReader::get(std::string_view key) const { return ok_ ? v_.find(key) : nullptr; }

const SourceValue* MapReader::require(std::string_view key) {
  const SourceValue* v = get(key);
  if (!v && ok_) r_.sink().error(v_.loc, fmt::format("{}: missing required key '{}'", what_, key), "");
  return v;
}

double MapReader::number(std::string_view key, double fallback, Range r) {
  const SourceValue* v = get(key);
  return v ? r_.number(*v, path(key), r) : fallback;
}

Param MapReader::param(std::string_view key, double fallback, Range r) {
  const SourceValue* v = get(key);
  return v ? r_.param(*v, path(key), r) : Param(fallback);
}

Param3 MapReader::param3(std::string_view key, Vec3d fallback, Range r) {
  const SourceValue* v = get(key);
  if (v) return r_.param3(*v, path(key), r);
  return {fallback[0], fallback[1], fallback[2]};
}

int MapReader::integer(std::string_view key, int fallback, int lo, int hi) {
  const SourceValue* v = get(key);
  return v ? r_.integer(*v, path(key), lo, hi) : fallback;
}

Vec3d MapReader::vec3(std::string_view key, Vec3d fallback, Range r) {
  const SourceValue* v = get(key);
  return v ? r_.vec3(*v, path(key), r) : fallback;
}

Vec3d MapReader::direction(std::string_view key, Vec3d fallback) {
  const SourceValue* v = get(key);
  return v ? r_.direction(*v, path(key)) : fallback;
}

std::string MapReader::word(std::string_view key, std::string fallback, std::initializer_list<std::string_view> choices) {
  const SourceValue* v = get(key);
  return v ? r_.word(*v, path(key), choices) : fallback;
}

}  // namespace sdfc::frontend
