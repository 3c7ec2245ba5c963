#pragma once
// Unlocked values: scene values the viewer's panel changes while the kernel
// runs. Instead of a literal, the kernel reads each from the frame block
// (after abi::kFrameFloats, in slot order), so a new value is a new frame,
// not a build. Only values that may be animated can be unlocked: the others
// (loop counts, choices, fractal constants) shape the kernel's code and are
// baked; changing one means a rebuild.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sdfc/source/source_value.hpp"

namespace sdfc {

struct UnlockSlot {
  int index = 0;
  std::string path;     // as asked for: "lights[0].intensity"
  bool ranged = false;  // lo/hi given; otherwise the reader picks them (frontend::unlock_range)
  double lo = 0, hi = 0;
  // Filled when the scene is read: the value in the file, and whether a reader
  // that allows run-time values took it.
  double value = 0;
  bool taken = false;
};
using UnlockSlots = std::vector<std::shared_ptr<UnlockSlot>>;

// "PATH" or "PATH=LO:HI". A path walks maps by key and lists by index, as
// "scene.union[1].sphere.radius" or "scene.union.1.sphere.radius".
struct UnlockRequest {
  std::string path;
  std::optional<std::pair<double, double>> range;
};
UnlockRequest parse_unlock(const std::string& text);  // SceneError on a bad range

// The value at `path`, or null.
const SourceValue* find_value(const SourceValue& root, const std::string& path);

// Marks the scalar values at the requests' paths in `root` (a SceneError for a
// path that names no number). build_module then checks that each was taken.
UnlockSlots mark_unlocked(SourceValue& root, const std::vector<UnlockRequest>& requests);

// The slots marked in `root`, in index order.
UnlockSlots marked_slots(const SourceValue& root);

// Throws a SceneError for each slot no run-time reader took, at its value.
void check_unlocked(const SourceValue& root, const UnlockSlots& slots);

// The floats that follow the frame block for these slots' current values.
std::vector<float> unlocked_values(const UnlockSlots& slots);

}  // namespace sdfc
