#pragma once
// Fractal nodes to OpenCL C: the call into the stdlib estimator with the
// node's parameters as literals, or (hybrid) an orbit loop written inline.
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::codegen::detail {

// True for the kinds emit_fractal handles.
bool is_fractal(const ir::Node& n);

// Writes any statements the node needs to `w` and returns the expression for
// its distance at point `p`; adds the stdlib functions it calls to `used`.
std::string emit_fractal(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                         std::set<std::string>& used);

// The node's colour value at `p` (evaluated once per hit): its orbit trap,
// or with `iteration` its smooth iteration count in [0, 1]. Writes any
// statements it needs to `w`; "" for kinds without one.
std::string emit_fractal_trap(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used, bool iteration);
// The fractal's iteration count at p for the iterations AOV: the escape
// iteration of escape-time fractals, the configured count of folding ones
// (which never escape) and of hybrids.
std::string emit_fractal_iterations(const ir::Node& n, const std::string& p, const Literals& lit,
                                    std::set<std::string>& used);

}  // namespace sdfc::codegen::detail
