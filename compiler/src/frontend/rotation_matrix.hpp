#pragma once
// The matrix of a `rotate:` modifier: rotations about up to three axes,
// multiplied (R = R0 * R1 * R2), as nine numbers or, with an animated
// angle, nine expressions of time.
#include <array>
#include <vector>

#include "sdfc/frontend/value_reader.hpp"

namespace sdfc::frontend {

// The first `count` (1 or 3) axes and angles, row-major, local->world.
std::array<double, 9> rotation_matrix(const std::array<Vec3d, 3>& axes, const Param3& deg, int count);
std::vector<Param> animated_rotation(const std::array<Vec3d, 3>& axes, const Param3& deg, int count);

}  // namespace sdfc::frontend
