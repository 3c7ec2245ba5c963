#pragma once
#include <string>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
// rows: pixel rows per packet (width / rows pixels per row).
// animated: the scene uses time, which then reaches every function that
// evaluates the scene as a first argument (TIME_PARAM / TIME_ARG).
// `unlocked`: values the scene functions read from the frame block's tail (sdfc/source/unlock.hpp).
// body: the rest of the kernel, which a packet wider than 16 lanes scans for
// the builtins it calls (wide_lanes.hpp).
std::string prelude(int width, int rows, ir::Precision precision, bool animated, int unlocked = 0,
                    const std::string& body = {});
}
