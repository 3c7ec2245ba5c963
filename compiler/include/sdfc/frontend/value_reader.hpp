#pragma once
// Typed reads from the source tree with located errors. Every read reports
// into a DiagnosticSink and returns a usable fallback, so one run can list
// all independent mistakes.
#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sdfc/expr/expr.hpp"
#include "sdfc/source/source_value.hpp"

namespace sdfc::frontend {

using Vec3d = std::array<double, 3>;

// The largest magnitude any scene number may have. Larger values only ever
// come from typos and break float precision in the kernel.
inline constexpr double kMaxMagnitude = 1e6;

struct Range {
  double lo = -kMaxMagnitude, hi = kMaxMagnitude;
  bool lo_open = false;  // lo itself excluded
  static Range positive(double hi = kMaxMagnitude) { return {0, hi, true}; }
  static Range non_negative(double hi = kMaxMagnitude) { return {0, hi, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false}; }
};

// The range an unlocked value `x` may take at run time when none is asked
// for: x +- max(|x|, 1), kept inside what the reader accepts (r). The panel's
// slider spans it; a value outside it means a rebuild with a new range.
std::pair<double, double> unlock_range(double x, const Range& r);

// A number that may be animated: an expression of `time` written as a
// string. `value` is its value at time 0; lo and hi bound it for every time
// in [0, expr::kMaxTime] (interval arithmetic); a static value has lo = hi.
struct Param {
  double value = 0;
  expr::ExprPtr anim;  // null when static
  double lo = 0, hi = 0;
  Param() = default;
  Param(double v) : value(v), lo(v), hi(v) {}  // NOLINT: a static number converts
  bool animated() const { return anim != nullptr; }
  Param scaled(double k) const;  // k * this
};
using Param3 = std::array<Param, 3>;

class ValueReader {
 public:
  explicit ValueReader(DiagnosticSink& sink) : sink_(sink) {}
  DiagnosticSink& sink() { return sink_; }

  // A number; a quoted expression without `time` ("2*pi"-like, folded) is
  // one too. An expression of `time` is refused: this value cannot be animated.
  double number(const SourceValue& v, std::string_view what, Range r = {});
  // A number that may be an expression of `time`; every value it takes over
  // time must lie in r.
  Param param(const SourceValue& v, std::string_view what, Range r = {});
  Param3 param3(const SourceValue& v, std::string_view what, Range r = {});
  int integer(const SourceValue& v, std::string_view what, int lo, int hi);
  Vec3d vec3(const SourceValue& v, std::string_view what, Range r = {});
  std::vector<double> vecn(const SourceValue& v, std::string_view what, size_t n, Range r = {});
  // One of `choices`; reports with a suggestion otherwise.
  std::string word(const SourceValue& v, std::string_view what, std::initializer_list<std::string_view> choices);
  // A vector that must not be (near) zero; returned normalised.
  Vec3d direction(const SourceValue& v, std::string_view what);

 private:
  // A quoted expression: parsed (null after a reported error), else nullptr
  // with *plain set when the value is not an expression at all.
  expr::ExprPtr expression(const SourceValue& v, bool* plain);
  // A plain number marked by mark_unlocked: a slot the kernel reads per frame (read_unlocked.cpp).
  Param unlocked(const SourceValue& v, std::string_view what, Range r);
  DiagnosticSink& sink_;
};

// A map with a fixed set of allowed keys. Unknown keys are reported once,
// with "did you mean" against the allowed ones.
class MapReader {
 public:
  MapReader(ValueReader& r, const SourceValue& v, std::string_view what,
            std::initializer_list<std::string_view> allowed);
  // Keys known only at run time (a formula preset's parameters).
  MapReader(ValueReader& r, const SourceValue& v, std::string_view what, const std::vector<std::string_view>& allowed);
  bool ok() const { return ok_; }
  const SourceValue* get(std::string_view key) const;
  const SourceValue& self() const { return v_; }

  double number(std::string_view key, double fallback, Range r = {});
  Param param(std::string_view key, double fallback, Range r = {});
  Param3 param3(std::string_view key, Vec3d fallback, Range r = {});
  int integer(std::string_view key, int fallback, int lo, int hi);
  Vec3d vec3(std::string_view key, Vec3d fallback, Range r = {});
  Vec3d direction(std::string_view key, Vec3d fallback);
  std::string word(std::string_view key, std::string fallback, std::initializer_list<std::string_view> choices);
  // Reports a missing required key at the map's location.
  const SourceValue* require(std::string_view key);

 private:
  std::string path(std::string_view key) const;
  ValueReader& r_;
  const SourceValue& v_;
  std::string what_;
  bool ok_ = true;
};

}  // namespace sdfc::frontend
