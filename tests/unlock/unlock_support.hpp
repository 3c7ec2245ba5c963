#pragma once
// A scene compiled from text with some values unlocked, and renders of a
// compiled kernel with the unlocked values' run-time numbers appended to the
// frame block.
#include <sdfrt/float_image.hpp>

#include <string>
#include <vector>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/module.hpp"
#include "sdfc/source/unlock.hpp"

namespace sdfc::test {

struct Unlocked {
  ir::Module module;
  UnlockSlots slots;
};
Unlocked compile_unlocked(const std::string& yaml, const std::vector<std::string>& unlocks);

inline constexpr int kWidth = 96, kHeight = 64, kSimd = 8;

// The image of `m` with `values` after the frame block (none for a baked kernel).
sdfrt::FloatImage render_with(const ir::Module& m, const std::vector<float>& values);
// The largest difference of any colour channel (0..1 scale).
double max_difference(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b);
// The share of pixels with a colour channel more than 1/255 apart.
double share_apart(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b);

}  // namespace sdfc::test
