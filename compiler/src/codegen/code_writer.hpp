#pragma once
// Small helpers shared by the emitter's parts: literals in the kernel's
// precision and an indenting line writer.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>

#include "sdfc/expr/expr.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/module.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::codegen::detail {

class Literals {
 public:
  explicit Literals(ir::Precision p) : p_(p) {}
  // Shortest spelling that reads back exactly in the kernel's precision.
  std::string real(double v) const {
    // Folded scales can multiply past the float range: the largest finite
    // value rather than "inff", which does not compile.
    if (p_ == ir::Precision::Float && std::isfinite(v) && !std::isfinite(static_cast<float>(v)))
      v = v > 0 ? std::numeric_limits<float>::max() : -std::numeric_limits<float>::max();
    std::string s = p_ == ir::Precision::Float ? fmt::format("{}", static_cast<float>(v)) : fmt::format("{}", v);
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return p_ == ir::Precision::Float ? s + "f" : s;
  }
  std::string vec3(const ir::Vec3d& v) const { return "v3(" + real(v[0]) + ", " + real(v[1]) + ", " + real(v[2]) + ")"; }
  // A real-typed constant (needed where both sides of select must be `real`).
  std::string typed(double v) const { return "(real)(" + real(v) + ")"; }

 private:
  ir::Precision p_;
};

// Parameter i of a node: a literal, or for an animated parameter its
// expression of `time` (a scalar the scene functions receive).
// A value that may be animated: the literal v, or e in OpenCL C.
inline std::string animated(const expr::ExprPtr& e, double v, const Literals& lit) {
  if (!e) return lit.real(v);
  return expr::to_opencl(
      e, [](std::string_view) { return std::string("time"); }, [&](double x) { return lit.real(x); });
}

inline std::string param(const ir::Node& n, size_t i, const Literals& lit) {
  return animated(n.animation(i), n.params[i], lit);
}

// Parameters i, i+1, i+2 as a vec3.
inline std::string param3(const ir::Node& n, size_t i, const Literals& lit) {
  if (!n.animation(i) && !n.animation(i + 1) && !n.animation(i + 2))
    return lit.vec3({n.params[i], n.params[i + 1], n.params[i + 2]});
  return "v3(" + param(n, i, lit) + ", " + param(n, i + 1, lit) + ", " + param(n, i + 2, lit) + ")";
}

class CodeWriter {
 public:
  void line(const std::string& s) { out_ += std::string(indent_ * 4, ' ') + s + "\n"; }
  void blank() { out_ += "\n"; }
  void open(const std::string& s) { line(s); ++indent_; }
  void close(const std::string& s = "}") { --indent_; line(s); }
  int fresh() { return next_++; }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
  int indent_ = 0;
  int next_ = 0;
};

}  // namespace sdfc::codegen::detail
