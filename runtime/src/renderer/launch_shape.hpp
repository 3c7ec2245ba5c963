#pragma once
// Internal: the work-group size a tile is launched with.
#include <sdfrt/device.hpp>

#include <array>
#include <cstddef>
#include <optional>

namespace sdfrt {

// The local size of a tile launch, or nullopt to let the driver choose
// (GPUs, where the driver knows its wavefronts).
//
// On CPU devices the driver's choice is measured to be poor for tiles:
// PoCL 3.1 packs a 64x64 launch into a few large work-groups, so one core
// idles while the other finishes the last group (the Mandelbulb bench frame:
// 175 ms with its choice, 135 ms with one work-item per group). Each
// work-group is one task for a CPU thread, so small groups balance the load;
// a packet work-item is already 16 pixels, and per-pixel kernels measured
// the same with 1x1, 8x8 and 16x1. One fixed size also means PoCL compiles
// its work-group function once, not once per edge-tile shape, and 1x1
// divides every launch.
std::optional<std::array<std::size_t, 2>> launch_local_size(DeviceType type);

}  // namespace sdfrt
