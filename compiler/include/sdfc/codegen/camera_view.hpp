#pragma once
// The camera as an image of a given size sees it: the field of view split
// into its two half-angle tangents by camera.fov_axis, and camera.fit
// (the camera moved back along its view direction until the scene's bounds
// fill the frame). Host code: the frame block, the viewer and the tests'
// own rays all go through these.
#include <array>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen {

// tan(horizontal fov / 2), tan(vertical fov / 2) at width x height.
std::array<double, 2> fov_tangents(const ir::Camera& c, int width, int height);

// The share of the frame (per side) the fitted bounds may fill.
inline constexpr double kFitFill = 0.9;

// With c.fit and a fit box: the camera looking along its direction at the
// box's centre from the nearest distance at which all eight corners of the
// box lie inside kFitFill of the frame. Otherwise c unchanged.
ir::Camera fitted(const ir::Camera& c, int width, int height);

}  // namespace sdfc::codegen
