#pragma once
// A chain's orbit as straight-line OpenCL C inside the scene function (the
// steps' numbers are literals), for its distance or one orbit value.
#include <set>
#include <string>

#include "sdfc/formula/step.hpp"  // the chain, and the emitter's classes declared

namespace sdfc::formula {

enum class Orbit { Distance, Trap, Smooth, Escape };

// Writes the orbit from point `p` to `w`; returns the variable holding the
// value. `measure`: the trap's measure of z ("" for the nearest coordinate plane).
std::string emit_chain(const Chain& c, const std::string& p, const codegen::detail::Literals& lit,
                       codegen::detail::CodeWriter& w, std::set<std::string>& used, Orbit what,
                       const std::string& measure = "");

}  // namespace sdfc::formula
