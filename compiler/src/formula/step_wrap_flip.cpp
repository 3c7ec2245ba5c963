// The steps of Jos Leys' Kleinian: wrap (z folded into one cell of a
// lattice, Mandelbulber's wrap()) and kleinian_flip (the half turn above a
// sine-shaped line). Both keep lengths: wrap is a translation by whole
// periods (derivative 1), the flip a point reflection (derivative -1).
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

const char* kAxes[3] = {"x", "y", "z"};

// ---- wrap: z_i -> z_i - period_i floor((z_i - start_i) / period_i), into
// [start_i, start_i + period_i)
void wrap_emit(const Step& st, EmitState& s) {
  for (int k = 0; k < 3; ++k)
    s.w.line(fmt::format("z.{0} = z.{0} - {1} * floor((z.{0} - {2}) / {1});  // wrap", kAxes[k], s.lit.real(st.a[size_t(k)]),
                         s.lit.real(st.a[size_t(3 + k)])));
}
void wrap_eval(const Step& st, RefState& s) {
  for (int k = 0; k < 3; ++k) {
    double p = st.a[size_t(k)];
    s.z[size_t(k)] -= p * std::floor((s.z[size_t(k)] - st.a[size_t(3 + k)]) / p);
  }
}

// ---- kleinian_flip: where y >= height (0.5 + 0.2 sin(sign(shift) pi (x + shift/2) / width)),
// z -> (-shift - x, height - y, -z): the half turn about (-shift/2, height/2, 0)
double flip_frequency(const Step& st) {
  const double b = st.a[1];
  return (b > 0 ? 1.0 : b < 0 ? -1.0 : 0.0) * M_PI / st.a[2];
}
void flip_emit(const Step& st, EmitState& s) {
  const double a = st.a[0], b = st.a[1];
  s.w.open("{  // kleinian_flip");
  s.w.line(fmt::format("mask up = z.y >= {} * (0.5f + 0.2f * sin({} * (z.x + {})));", s.lit.real(a),
                       s.lit.real(flip_frequency(st)), s.lit.real(0.5 * b)));
  s.w.line(fmt::format("z = v3_select(z, v3_sub({}, z), up);", s.lit.vec3({-b, a, 0})));
  if (s.jacobian)
    s.w.line(fmt::format("ja = v3_select(ja, v3_scale(ja, {0}), up); jb = v3_select(jb, v3_scale(jb, {0}), up); "
                         "jc = v3_select(jc, v3_scale(jc, {0}), up);",
                         s.lit.typed(-1)));
  s.w.close();
}
void flip_eval(const Step& st, RefState& s) {
  const double a = st.a[0], b = st.a[1];
  if (s.z[1] < a * (0.5 + 0.2 * std::sin(flip_frequency(st) * (s.z[0] + 0.5 * b)))) return;
  s.z = {-b - s.z[0], a - s.z[1], -s.z[2]};
  for (V3& c : s.j)
    for (double& v : c) v = -v;
}

}  // namespace

extern const StepDef kWrap{"wrap",
                           {{"period", 3, {2, 2, 2}, false, 1e-6, 1e6}, {"start", 3, {-1, -1, -1}}},
                           always_conformal, false, wrap_emit, wrap_eval,
                           "moves each coordinate by whole periods into [start, start + period) (a lattice of cells)",
                           false, keeps_dr};
extern const StepDef kKleinianFlip{"kleinian_flip",
                                   {{"height", 1, {2}, false, 1e-6, 1e6}, {"shift", 1, {0}}, {"width", 1, {1}, false, 1e-6, 1e6}},
                                   always_conformal, false, flip_emit, flip_eval,
                                   "above y = height (0.5 + 0.2 sin(sign(shift) pi (x + shift/2) / width)) turns z half "
                                   "round (-shift/2, height/2, 0) (Jos Leys' Kleinian)",
                                   false, keeps_dr};

}  // namespace sdfc::formula
