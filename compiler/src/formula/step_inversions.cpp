// The inversions and the folds of the Mandelbulber formulas built on them:
// spherical_invert, kleinian_fold (the pseudo-Kleinian's sphere inversion),
// surf_fold (the Amazing Surf's fold on chosen axes). An inversion in a
// sphere is conformal with the factor R^2 / r^2; its Jacobian is
// f (I - 2 w w^T / r^2) on the columns (stdlib fold_inversion_j).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

const char* kAxes[3] = {"x", "y", "z"};

// Columns c -> f (c - k w (w.c)): the inversion's derivative where k = 2 / r^2.
void invert_columns(RefState& s, const V3& w, double f, double k) {
  for (V3& c : s.j) {
    double d = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
    for (int i = 0; i < 3; ++i) c[i] = (c[i] - k * d * w[i]) * f;
  }
}

// ---- spherical_invert: z -> centre + R^2 (z - centre) / |z - centre|^2
void invert_emit(const Step& st, EmitState& s) {
  std::string r2 = s.lit.real(st.a[0] * st.a[0]), ctr = s.lit.vec3({st.a[1], st.a[2], st.a[3]});
  s.w.open("{  // spherical_invert");
  s.w.line(fmt::format("vec3 w = v3_sub(z, {});", ctr));
  s.w.line("real q = fmax(v3_dot(w, w), K(1e-30f));");
  s.w.line(fmt::format("real f = {} / q;", r2));
  if (s.jacobian) {
    s.used.insert("fold_inversion_j");
    s.w.line("fold_inversion_j(w, &ja, &jb, &jc, f, 2.0f / q);");
  } else {
    s.w.line("dr = dr * f;");
  }
  s.w.line(fmt::format("z = v3_add({}, v3_scale(w, f));", ctr));
  s.w.close();
}
// f = R^2 / |w|^2 with w = z - centre: grad f = -2 f w / |w|^2
DualFactor invert_dual(const Step& st, EmitState& s) {
  return {{fmt::format("const vec3 w = v3_sub(z, {});", s.lit.vec3({st.a[1], st.a[2], st.a[3]})),
           "const real q = fmax(v3_dot(w, w), K(1e-30f));", fmt::format("const real f = {} / q;", s.lit.real(st.a[0] * st.a[0]))},
          "f", "v3_scale(w, -2.0f * f / q)"};
}
void invert_eval(const Step& st, RefState& s) {
  V3 w{s.z[0] - st.a[1], s.z[1] - st.a[2], s.z[2] - st.a[3]};
  double q = std::max(w[0] * w[0] + w[1] * w[1] + w[2] * w[2], 1e-30), f = st.a[0] * st.a[0] / q;
  invert_columns(s, w, f, 2 / q);
  s.dr *= f;
  for (int i = 0; i < 3; ++i) s.z[i] = st.a[1 + i] + w[i] * f;
}

// ---- kleinian_fold: inside the sphere r^2 < min_r2, invert in it
// (k = min_r2 / r^2); the scalar derivative takes k + de_tweak (Mandelbulber's
// analytic DE tweak), the Jacobian the inversion's exact derivative.
void kleinian_emit(const Step& st, EmitState& s) {
  s.w.open("{  // kleinian_fold");
  s.w.line("real q = fmax(v3_dot(z, z), K(1e-30f));");
  s.w.line(fmt::format("real k = fmax({} / q, K(1.0f));", s.lit.real(st.a[0])));
  if (s.jacobian) {
    s.used.insert("fold_inversion_j");
    s.w.line(fmt::format("fold_inversion_j(z, &ja, &jb, &jc, k, SEL((real)(0.0f), 2.0f / q, q < {}));", s.lit.real(st.a[0])));
  } else {
    s.w.line(fmt::format("dr = dr * (k + {});", s.lit.real(st.a[1])));
  }
  s.w.line("z = v3_scale(z, k);");
  s.w.close();
}
// f = k + de_tweak, k = max(min_r2 / |z|^2, 1): grad -2 k z / |z|^2 inside the sphere
DualFactor kleinian_dual(const Step& st, EmitState& s) {
  const std::string m2 = s.lit.real(st.a[0]);
  return {{"const real q = fmax(v3_dot(z, z), K(1e-30f));", fmt::format("const real k = fmax({} / q, K(1.0f));", m2)},
          fmt::format("(k + {})", s.lit.real(st.a[1])),
          fmt::format("v3_scale(z, SEL((real)(0.0f), -2.0f * k / q, q < {}))", m2)};
}
void kleinian_eval(const Step& st, RefState& s) {
  const V3 w = s.z;
  double q = std::max(w[0] * w[0] + w[1] * w[1] + w[2] * w[2], 1e-30), k = std::max(st.a[0] / q, 1.0);
  invert_columns(s, w, k, q < st.a[0] ? 2 / q : 0.0);
  s.dr *= k + st.a[1];
  for (double& v : s.z) v *= k;
}

// ---- surf_fold: z_i -> |z_i + l_i| - |z_i - l_i| - z_i on the axes whose flag
// is 1 (Amazing Surf folds x and y); a reflection beyond +-l_i
void surf_emit(const Step& st, EmitState& s) {
  for (int k = 0; k < 3; ++k) {
    if (st.a[3 + k] == 0) continue;
    std::string l = s.lit.real(st.a[k]);
    if (s.jacobian)
      s.w.line(fmt::format("{{ real sg = SEL((real)(1.0f), (real)(-1.0f), fabs(z.{0}) > {1}); ja.{0} *= sg; jb.{0} *= sg; "
                           "jc.{0} *= sg; }}",
                           kAxes[k], l));
    s.w.line(fmt::format("z.{0} = clamp(z.{0}, -{1}, {1}) * 2.0f - z.{0};  // surf_fold", kAxes[k], l));
  }
}
void surf_eval(const Step& st, RefState& s) {
  for (int k = 0; k < 3; ++k) {
    if (st.a[3 + k] == 0) continue;
    double l = st.a[k];
    if (std::fabs(s.z[k]) > l)
      for (V3& c : s.j) c[k] = -c[k];
    s.z[k] = std::fabs(s.z[k] + l) - std::fabs(s.z[k] - l) - s.z[k];
  }
}

}  // namespace

extern const StepDef kSphericalInvert{"spherical_invert",
                                      {{"radius", 1, {1}, false, 1e-6, 1e6}, {"centre", 3, {0, 0, 0}}},
                                      always_conformal, false, invert_emit, invert_eval,
                                      "inverts z in the sphere of radius about centre", false, invert_dual};
extern const StepDef kKleinianFold{"kleinian_fold",
                                   {{"min_r2", 1, {0.5}, false, 1e-6, 1e6}, {"de_tweak", 1, {0}, false, 0, 10}},
                                   always_conformal, false, kleinian_emit, kleinian_eval,
                                   "inverts z in the sphere r^2 = min_r2 when inside it (the pseudo-Kleinian's fold)", false,
                                   kleinian_dual};
extern const StepDef kSurfFold{"surf_fold",
                               {{"limit", 3, {1, 1, 1}, false, 1e-6, 1e6}, {"axes", 3, {1, 1, 0}, false, 0, 1}},
                               always_conformal, false, surf_emit, surf_eval,
                               "|z + limit| - |z - limit| - z on the axes whose flag is 1 (the Amazing Surf fold)", false,
                               keeps_dr};

}  // namespace sdfc::formula
