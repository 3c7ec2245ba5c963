#pragma once
// Internal: the work-group size a tile is launched with.
#include <sdfrt/device.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace sdfrt {

// The local size for a launch of groups_x x groups_y work-items, or nullopt
// to let the driver choose (GPUs, where the driver knows its wavefronts).
//
// On CPU devices the driver's choice is measured to be poor: PoCL 3.1 packs a
// 64x64 launch into a handful of large work-groups, so one core idles while
// the other finishes the last group (the Mandelbulb bench frame: 175 ms with
// 256-pixel tiles, 141 ms with small groups). Each work-group is one task
// for a CPU thread, so small groups balance the load; a packet work-item is
// already 16 pixels, so one per group costs nothing measurable, and a
// per-pixel work-item gets a few rows of neighbours (the largest of 8/4/2/1
// dividing the launch, as OpenCL 1.2 requires).
std::optional<std::array<std::size_t, 2>> launch_local_size(DeviceType type, int simd_width,
                                                            std::size_t groups_x,
                                                            std::size_t groups_y);

}  // namespace sdfrt
