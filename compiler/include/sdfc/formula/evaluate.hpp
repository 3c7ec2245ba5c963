#pragma once
// A chain evaluated in double: the CPU reference of its distance and orbit.
#include <array>
#include <functional>

#include "sdfc/formula/chain.hpp"

namespace sdfc::formula {

struct OrbitResult {
  double distance;
  double trap;        // the smallest measure over the orbit
  double iterations;  // steps before |z| passed the bailout
  double r;           // |z| at the end
};

// `measure`: the orbit trap's measure of z (default: the smallest |coordinate|).
OrbitResult evaluate(const Chain& c, const std::array<double, 3>& p,
                     const std::function<double(const std::array<double, 3>&)>& measure = {});

}  // namespace sdfc::formula
