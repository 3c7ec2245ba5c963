#include "viewer/resolution_governor.hpp"

#include <iterator>

namespace sdfc::viewer {

namespace {
constexpr int kDivisors[] = {1, 2, 3, 4, 6, 8};
}

int ResolutionGovernor::divisor(int width, int height) const {
  if (!calibrated()) return 4;  // a safe first guess; refined after one frame
  for (int d : kDivisors) {
    long long pixels = static_cast<long long>(width / d) * (height / d);
    if (pixels * ns_per_pixel_ * 1e-6 <= budget_ms_) return d;
  }
  return kDivisors[std::size(kDivisors) - 1];
}

void ResolutionGovernor::record(long long pixels, double ms) {
  if (pixels <= 0 || ms <= 0) return;
  double sample = ms * 1e6 / double(pixels);
  // Smooth, but follow quickly: the cost changes as the view changes.
  ns_per_pixel_ = calibrated() ? 0.6 * ns_per_pixel_ + 0.4 * sample : sample;
}

}  // namespace sdfc::viewer
