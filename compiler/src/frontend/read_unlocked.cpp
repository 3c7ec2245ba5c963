// Unlocked values (sdfc/source/unlock.hpp): the number in the file becomes
// a slot the kernel reads from the frame block, with the range the compiler
// assumes for its bounds and checks.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/source/unlock.hpp"

namespace sdfc::frontend {

namespace {
bool inside(double x, const Range& r) { return !(r.lo_open ? x <= r.lo : x < r.lo) && x <= r.hi; }
}  // namespace

std::pair<double, double> unlock_range(double x, const Range& r) {
  const double span = std::max(std::fabs(x), 1.0);
  double lo = x - span, hi = std::min(x + span, r.hi);
  // Towards an open end (a radius > 0) stop at an eighth of the way, never on it.
  if (!inside(lo, r)) lo = r.lo_open ? r.lo + (x - r.lo) * 0.125 : r.lo;
  return {lo, hi};
}

Param ValueReader::unlocked(const SourceValue& v, std::string_view what, Range r) {
  UnlockSlot& s = *v.unlock;
  const double x = number(v, what, r);
  if (!s.ranged) std::tie(s.lo, s.hi) = unlock_range(x, r);
  if (!inside(s.lo, r) || !inside(s.hi, r) || x < s.lo || x > s.hi) {
    sink_.error(v.loc, fmt::format("--unlock {}={}:{}: {} must stay within its allowed values and hold {} (the value in the file)",
                                   s.path, s.lo, s.hi, what, x),
                "give a range inside the allowed values that holds the current value");
    return x;
  }
  s.value = x;
  s.taken = true;
  Param p;
  p.value = x;
  p.lo = s.lo, p.hi = s.hi;
  p.anim = expr::slot(s.index, x, s.lo, s.hi);
  return p;
}

}  // namespace sdfc::frontend
