#pragma once
#include <string>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {
std::string prelude(int width, ir::Precision precision);
}
