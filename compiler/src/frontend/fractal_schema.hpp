#pragma once
// The fractal part of the geometry schema (issue 3): mandelbulb (and its
// julia form), mandelbox, quaternion julia, menger, sierpinski, kifs, hybrid.
#include <string_view>
#include <vector>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::frontend {

// The fractal kind names a scene may use.
const std::vector<std::string_view>& fractal_kinds();

// Lowers one fractal node; kNoNode after reporting an error.
ir::NodeId lower_fractal(ValueReader& r, ir::Builder& b, const SourceValue& key, const SourceValue& body);

}  // namespace sdfc::frontend
