#pragma once
// Material shares across smooth blends, for the reference evaluator.
#include <functional>

#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference::detail {

// The share of b in blend(a, b): its derivative in b, by a central
// difference (written from the blend itself, not from the stdlib's
// closed forms, so the two check each other).
double share_of_b(const std::function<double(double, double)>& blend, double a, double b);

// A blended sample: `distance` and `material` given, the shares of a and b
// mixed with weight wb for b.
Sample mix_samples(const Sample& a, const Sample& b, double wb, double distance, int material);

// A material node's claim on the parts of s that have none yet (id 0).
void claim(Sample& s, int material);

}  // namespace sdfc::reference::detail
