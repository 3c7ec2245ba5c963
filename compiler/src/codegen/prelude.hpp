#pragma once
#include <string>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
// rows: pixel rows per packet (width / rows pixels per row).
std::string prelude(int width, int rows, ir::Precision precision);
}
