#pragma once
// One step of a formula chain: how it is read, whether its derivative is a
// scalar factor (conformal) or needs the Jacobian, how it is written in
// OpenCL and evaluated in double. One definition per step (or small family)
// in compiler/src/formula/step_*.cpp; step_table.cpp lists them.
#include <array>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "sdfc/formula/chain.hpp"

namespace sdfc::codegen::detail {
class CodeWriter;
class Literals;
}  // namespace sdfc::codegen::detail

namespace sdfc::formula {

using V3 = std::array<double, 3>;

// A number the step reads: a scalar or a vec3, with its default (`required`
// when there is none) and its range.
struct StepParam {
  std::string_view name;
  int width;  // 1 or 3
  std::array<double, 3> fallback;
  bool required = false;
  double lo = -1e6, hi = 1e6;
  std::vector<std::string_view> words = {};  // a word-valued setting: stored as its index here
};

// The orbit's state in double for the reference: z, the scalar derivative
// and the Jacobian's columns (dz/dpx, dz/dpy, dz/dpz), and what add_c adds.
// A 4-D chain adds w, its row of the Jacobian (dw/dp) and c's w.
struct RefState {
  V3 z;
  double dr = 1;
  std::array<V3, 3> j{V3{1, 0, 0}, V3{0, 1, 0}, V3{0, 0, 1}};
  V3 c;
  bool mandel = true;  // c = p: add_c adds the identity to J and 1 to dr
  bool jacobian = false;
  bool four_d = false;
  double w = 0, cw = 0;
  V3 jw{0, 0, 0};
};

// Where the emitter keeps the state: z, dr (scalar) or ja/jb/jc (columns),
// c (the vec3 add_c adds) and `id` (1 when c = p, else 0). A 4-D chain adds
// the reals zw (z's w) and cw (c's w) and, with the Jacobian, the vec3 jw (dw/dp).
struct EmitState {
  codegen::detail::CodeWriter& w;
  const codegen::detail::Literals& lit;
  std::set<std::string>& used;
  bool jacobian;
  int fresh = 0;  // names temporaries
  bool four_d = false;
  // render.normals: dual: the scalar derivative dr and its gradient gdr run
  // beside the Jacobian (jacobian is true too); each step's `dual` rule
  // updates them before the step's own code.
  bool dual = false;
  std::string tmp(const char* base) { return base + std::to_string(fresh++); }
};

// render.normals: dual: how a step changes the scalar derivative,
// dr <- f dr + adds, as expressions of z (and zw) as the step receives it,
// with f's gradient in z (and w); "" stands for f = 1, a zero gradient and
// nothing added. The emitter carries grad dr through the Jacobian:
// grad f = J^T grad_z + grad_w jw. `temps`: statements the expressions need
// (written in a block of their own).
struct DualFactor {
  std::vector<std::string> temps = {};
  std::string f = "";
  std::string grad_z = "";
  std::string grad_w = "";
  std::string adds = "";
};

struct StepDef {
  std::string_view name;
  std::vector<StepParam> params;  // a scalar shorthand (`scale: 2`) sets the first
  // Conformal: the derivative is a scalar factor (folds, rotations, uniform
  // scales, powers); otherwise the chain needs the running Jacobian.
  bool (*conformal)(const Step&);
  bool power;  // grows like a power of |z|: the log estimator fits
  void (*emit)(const Step&, EmitState&);
  void (*eval)(const Step&, RefState&);
  std::string_view what;  // one line for the docs and `sdfc check`
  bool four_d = false;    // reads or writes w: the chain carries a 4-D z
  // render.normals: dual: its rule for the scalar derivative (null: a chain
  // with this step has no dual normals).
  DualFactor (*dual)(const Step&, EmitState&) = nullptr;
};

const std::vector<const StepDef*>& steps();  // every step, by name
const StepDef* find_step(std::string_view name);

// Shared helpers of the step files.
bool always_conformal(const Step&);
// The dual rule of a step that keeps dr (reflections, rotations, translations).
DualFactor keeps_dr(const Step&, EmitState&);
// Applies the linear map `m` (row-major) to every Jacobian column.
void apply_rows(RefState& s, const std::array<double, 9>& m);
// 4-D steps (step_four_d.cpp): the 4x4 Jacobian `m` of the step (row-major
// over x, y, z, w) applied to the columns (ja, jw.x), (jb, jw.y), (jc, jw.z).
// Emitted: its entries as expressions of the old z and w ("" for 0), written
// before the step changes z.
void emit_rows4(EmitState& s, const std::array<std::string, 16>& m);
void apply_rows4(RefState& s, const std::array<double, 16>& m);

}  // namespace sdfc::formula

namespace sdfc::formula {
// Fills an expr step's partials, its tape (x, y, z, then the partials) and
// whether it is linear (the reader calls it once).
void differentiate(Step& st);
}  // namespace sdfc::formula
