#pragma once
// A chain's orbit as straight-line OpenCL C inside the scene function (the
// steps' numbers are literals), for its distance or one orbit value.
#include <set>
#include <string>

#include "sdfc/formula/step.hpp"  // the chain, and the emitter's classes declared

namespace sdfc::formula {

// Gradient (render.normals: dual): the gradient of the distance estimate, a
// vec3; only for a chain dual_blocker accepts.
enum class Orbit { Distance, Trap, Smooth, Escape, Gradient };

// Writes the orbit from point `p` to `w`; returns the variable holding the
// value. `measure`: the trap's measure of z ("" for the nearest coordinate plane).
std::string emit_chain(const Chain& c, const std::string& p, const codegen::detail::Literals& lit,
                       codegen::detail::CodeWriter& w, std::set<std::string>& used, Orbit what,
                       const std::string& measure = "");

// Why render.normals: dual cannot differentiate the chain's estimate (a
// step with no dual rule, or a running-Jacobian estimate, whose gradient
// needs second derivatives), naming the step; "" when it can.
std::string dual_blocker(const Chain& c);

// emit_chain's end for Orbit::Gradient: the estimate's gradient from the
// orbit's end state (z, r, ja/jb/jc, dr, gdr) into the vec3 `out`.
void emit_estimate_gradient(const Chain& c, const Plan& pl, const std::string& p, const codegen::detail::Literals& lit,
                            codegen::detail::CodeWriter& w, const std::string& out);

}  // namespace sdfc::formula
