#pragma once
// Fractal nodes to OpenCL C: the call into the stdlib estimator with the
// node's parameters as literals, or (hybrid) an orbit loop written inline,
// as each fractal's description (compiler/src/kinds/) writes it.
#include <optional>
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

// The values of the node's orbit from `p` (evaluated once per hit or pixel,
// never in the march): its orbit trap, its smooth iteration count in [0, 1]
// (an orbit-trap material's `source: iteration`), or its escape iteration
// for the iterations AOV (the configured count of folding fractals, which
// never escape, and of hybrids).
enum class OrbitValue { Trap, Smooth, Escape };

// The node's orbit value at `p`. Writes any statements it needs to `w`; ""
// for kinds without an orbit. `shape`: the material whose trap shape the
// trap takes (trap_shape_emitter.hpp); none for the default shape.
std::string emit_fractal_trap(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used, OrbitValue value, std::optional<size_t> shape = std::nullopt);

// render.normals: dual: the direction of grad |z_n| at `p` (forward-mode
// dual numbers through the orbit); "" for kinds without it.
std::string emit_fractal_dual(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used);

}  // namespace sdfc::codegen::detail
