#pragma once
#include <string>

namespace sdfc::codegen::detail {
// The `real` and `mask` types of a packet wider than 16 lanes (32 or 64),
// with an overload, for those types, of each OpenCL builtin that `body`
// calls. scalar: float or double; mask_scalar: int or long.
std::string wide_lane_types(int width, const std::string& scalar, const std::string& mask_scalar,
                            const std::string& body);
}
