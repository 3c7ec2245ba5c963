#pragma once
// Positive values so small that what the kernel computes from them is no
// float (1/scale, 1/gamma) or renders nothing (a zero normal step, a field
// of view of one ray): refused with the smallest value that works.
#include <fmt/format.h>

#include <string_view>

#include "sdfc/frontend/value_reader.hpp"

namespace sdfc::frontend {

inline constexpr double kMinScale = 1e-4;

inline void too_small(ValueReader& r, const SourceValue& v, std::string_view what, double got, double min) {
  r.sink().error(v.loc, fmt::format("{}: {:g} is too small; the smallest value that renders is {:g}", what, got, min));
}

}  // namespace sdfc::frontend
