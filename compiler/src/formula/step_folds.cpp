// The folds: piecewise reflections (box, abs, plane, the symmetry groups)
// and the sphere fold. A reflection keeps |dz| (the scalar derivative is
// unchanged) and reflects the Jacobian's columns with z.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

using codegen::detail::CodeWriter;

const char* kAxes[3] = {"x", "y", "z"};

// Reflects v in the plane through the origin with unit normal n.
void reflect(V3& v, const V3& n) {
  double t = 2 * (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
  for (int k = 0; k < 3; ++k) v[k] -= t * n[k];
}
// Reflects z (and the Jacobian's columns) where `on` holds.
void reflect_all(RefState& s, const V3& n, bool on) {
  if (!on) return;
  reflect(s.z, n);
  for (V3& c : s.j) reflect(c, n);
}
std::string jac_args() { return "&z, &ja, &jb, &jc"; }

// ---- box_fold: each coordinate beyond +-limit reflected back into the box
void box_emit(const Step& st, EmitState& s) {
  std::string l = s.lit.real(st.a[0]);
  if (s.jacobian)
    s.w.line(fmt::format("{{ vec3 fl = v3(SEL((real)(1.0f), (real)(-1.0f), fabs(z.x) > {0}), SEL((real)(1.0f), (real)(-1.0f), "
                         "fabs(z.y) > {0}), SEL((real)(1.0f), (real)(-1.0f), fabs(z.z) > {0})); ja = v3_mul(ja, fl); "
                         "jb = v3_mul(jb, fl); jc = v3_mul(jc, fl); }}",
                         l));
  s.w.line(fmt::format("z = v3(clamp(z.x, -{0}, {0}) * 2.0f - z.x, clamp(z.y, -{0}, {0}) * 2.0f - z.y, "
                       "clamp(z.z, -{0}, {0}) * 2.0f - z.z);  // box_fold",
                       l));
}
void box_eval(const Step& st, RefState& s) {
  double l = st.a[0];
  for (int k = 0; k < 3; ++k) {
    if (std::fabs(s.z[k]) > l)
      for (V3& c : s.j) c[k] = -c[k];
    s.z[k] = std::clamp(s.z[k], -l, l) * 2 - s.z[k];
  }
}

// ---- sphere_fold: scale up inside min_radius, invert between the radii
void sphere_emit(const Step& st, EmitState& s) {
  std::string m2 = s.lit.real(st.a[0] * st.a[0]), f2 = s.lit.real(st.a[1] * st.a[1]);
  if (s.jacobian) {
    s.used.insert("fold_sphere_j");
    s.w.line(fmt::format("fold_sphere_j({}, {}, {});", jac_args(), m2, f2));
  } else {
    s.used.insert("fold_sphere");
    s.w.line(fmt::format("z = fold_sphere(z, {}, {}, &dr);", m2, f2));
  }
}
// f = fixed_r2 / min_r2 inside, fixed_r2 / r2 in the shell (grad -2 f z / r2), 1 outside
DualFactor sphere_dual(const Step& st, EmitState& s) {
  std::string m2 = s.lit.real(st.a[0] * st.a[0]), f2 = s.lit.real(st.a[1] * st.a[1]);
  return {{"const real q = fmax(v3_dot(z, z), K(1e-30f));",
           fmt::format("const real f = SEL(SEL((real)(1.0f), {1} / q, q < {1}), {1} / {0}, q < {0});", m2, f2)},
          "f",
          fmt::format("v3_scale(z, SEL((real)(0.0f), -2.0f * f / q, (q >= {}) & (q < {})))", m2, f2)};
}
void sphere_eval(const Step& st, RefState& s) {
  double m2 = st.a[0] * st.a[0], f2 = st.a[1] * st.a[1];
  const V3 w = s.z;
  double r2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  bool inner = r2 < m2, shell = !inner && r2 < f2;
  double f = inner ? f2 / m2 : shell ? f2 / std::max(r2, 1e-300) : 1.0;
  double k = shell ? 2 / std::max(r2, 1e-300) : 0.0;
  for (V3& c : s.j) {
    double d = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
    for (int i = 0; i < 3; ++i) c[i] = (c[i] - k * d * w[i]) * f;
  }
  for (double& v : s.z) v *= f;
  s.dr *= f;
}

// ---- abs: |coordinate| on the axes whose flag is non-zero
void abs_emit(const Step& st, EmitState& s) {
  for (int k = 0; k < 3; ++k) {
    if (st.a[k] == 0) continue;
    if (s.jacobian)
      s.w.line(fmt::format("{{ real sg = SEL((real)(1.0f), (real)(-1.0f), z.{0} < 0.0f); ja.{0} *= sg; jb.{0} *= sg; jc.{0} *= sg; }}",
                           kAxes[k]));
    s.w.line(fmt::format("z.{0} = fabs(z.{0});  // abs", kAxes[k]));
  }
}
void abs_eval(const Step& st, RefState& s) {
  for (int k = 0; k < 3; ++k) {
    if (st.a[k] == 0 || s.z[k] >= 0) continue;
    s.z[k] = -s.z[k];
    for (V3& c : s.j) c[k] = -c[k];
  }
}

// ---- plane_fold: reflect where z.n > offset into the other side
V3 unit(const Step& st) {
  double l = std::sqrt(st.a[0] * st.a[0] + st.a[1] * st.a[1] + st.a[2] * st.a[2]);
  return {st.a[0] / l, st.a[1] / l, st.a[2] / l};
}
void plane_emit(const Step& st, EmitState& s) {
  V3 n = unit(st);
  std::string nv = s.lit.vec3(n), off = s.lit.real(st.a[3]);
  if (s.jacobian) {
    // Shift the plane to the origin, reflect, shift back; the negated offset is its own literal so a
    // negative offset never prints as "--".
    s.used.insert("fold_reflect_j");
    s.w.line(fmt::format("{{ mask side = v3_dot(z, {0}) > {1}; z = v3_mad(z, {0}, {3}); fold_reflect_j({2}, {0}, side); "
                         "z = v3_mad(z, {0}, {1}); }}  // plane_fold",
                         nv, off, jac_args(), s.lit.real(-st.a[3])));
  } else {
    s.w.line(fmt::format("z = v3_mad(z, {0}, -2.0f * fmax(v3_dot(z, {0}) - {1}, K(0.0f)));  // plane_fold", nv, off));
  }
}
void plane_eval(const Step& st, RefState& s) {
  V3 n = unit(st);
  double t = s.z[0] * n[0] + s.z[1] * n[1] + s.z[2] * n[2] - st.a[3];
  if (t <= 0) return;
  for (int k = 0; k < 3; ++k) s.z[k] -= 2 * t * n[k];
  for (V3& c : s.j) reflect(c, n);
}

// ---- octa_fold: the cube's symmetry (abs, sort x >= y >= z)
const double kH = std::sqrt(0.5);
void octa_ref(RefState& s) {
  reflect_all(s, {1, 0, 0}, s.z[0] < 0);
  reflect_all(s, {0, 1, 0}, s.z[1] < 0);
  reflect_all(s, {0, 0, 1}, s.z[2] < 0);
  reflect_all(s, {-kH, kH, 0}, s.z[1] > s.z[0]);
  reflect_all(s, {-kH, 0, kH}, s.z[2] > s.z[0]);
  reflect_all(s, {0, -kH, kH}, s.z[2] > s.z[1]);
}
// A symmetry fold: its stdlib function on z, or its _j form on z and the Jacobian.
void symmetry_fold(EmitState& s, const std::string& jacobian_fn, const std::string& fn) {
  s.used.insert(s.jacobian ? jacobian_fn : fn);
  s.w.line(s.jacobian ? jacobian_fn + "(" + jac_args() + ");" : "z = " + fn + "(z);");
}
void octa_emit(const Step&, EmitState& s) { symmetry_fold(s, "fold_octa_j", "fold_cube"); }
void octa_eval(const Step&, RefState& s) { octa_ref(s); }

// ---- tetra_fold: the tetrahedron's symmetry
void tetra_emit(const Step&, EmitState& s) { symmetry_fold(s, "fold_tetra_j", "fold_tetra"); }
void tetra_eval(const Step&, RefState& s) {
  reflect_all(s, {kH, kH, 0}, s.z[0] + s.z[1] < 0);
  reflect_all(s, {kH, 0, kH}, s.z[0] + s.z[2] < 0);
  reflect_all(s, {0, kH, kH}, s.z[1] + s.z[2] < 0);
}

// ---- menger_fold: one Menger sponge step: octa_fold, scale about the
// corner `offset`, fold the middle layer back (z.z += shift below -shift/2)
void menger_emit(const Step& st, EmitState& s) {
  octa_emit(st, s);
  double k = st.a[0], shift = st.a[3] * (k - 1);
  s.w.line(fmt::format("z = v3_sub(v3_scale(z, {}), {});  // menger_fold scale {}", s.lit.real(k),
                       s.lit.vec3({st.a[1] * (k - 1), st.a[2] * (k - 1), shift}), k));
  s.w.line(fmt::format("z.z = SEL(z.z, z.z + {0}, z.z < {1});", s.lit.real(shift), s.lit.real(-0.5 * shift)));
  if (s.jacobian)
    s.w.line(fmt::format("ja = v3_scale(ja, {0}); jb = v3_scale(jb, {0}); jc = v3_scale(jc, {0});", s.lit.real(k)));
  else
    s.w.line(fmt::format("dr = dr * {};", s.lit.real(std::fabs(k))));
}
DualFactor menger_dual(const Step& st, EmitState& s) { return {.f = s.lit.real(std::fabs(st.a[0]))}; }
void menger_eval(const Step& st, RefState& s) {
  octa_ref(s);
  double k = st.a[0], shift = st.a[3] * (k - 1);
  for (int i = 0; i < 3; ++i) s.z[i] = s.z[i] * k - st.a[1 + i] * (k - 1);
  if (s.z[2] < -0.5 * shift) s.z[2] += shift;
  for (V3& c : s.j)
    for (double& v : c) v *= k;
  s.dr *= std::fabs(k);
}

}  // namespace

extern const StepDef kBoxFold{"box_fold", {{"limit", 1, {1}, false, 1e-6, 1e6}}, always_conformal, false, box_emit, box_eval,
                              "reflects each coordinate beyond +-limit back into the box", false, keeps_dr};
extern const StepDef kSphereFold{"sphere_fold",
                                 {{"min_radius", 1, {0.5}, false, 1e-6, 1e6}, {"fixed_radius", 1, {1}, false, 1e-6, 1e6}},
                                 always_conformal, false, sphere_emit, sphere_eval,
                                 "scales up inside min_radius, inverts in the fixed sphere between the radii", false,
                                 sphere_dual};
extern const StepDef kAbs{"abs", {{"axes", 3, {1, 1, 1}, false, 0, 1}}, always_conformal, false, abs_emit, abs_eval,
                          "the absolute value of the coordinates whose flag in axes is 1", false, keeps_dr};
extern const StepDef kPlaneFold{"plane_fold", {{"normal", 3, {1, 0, 0}, true}, {"offset", 1, {0}}}, always_conformal, false,
                                plane_emit, plane_eval, "reflects the side where z.normal > offset to the other side", false,
                                keeps_dr};
extern const StepDef kOctaFold{"octa_fold", {}, always_conformal, false, octa_emit, octa_eval,
                               "the cube's symmetry: abs, then sorts x >= y >= z", false, keeps_dr};
extern const StepDef kTetraFold{"tetra_fold", {}, always_conformal, false, tetra_emit, tetra_eval,
                                "the tetrahedron's symmetry: reflects in x+y=0, x+z=0, y+z=0", false, keeps_dr};
extern const StepDef kMengerFold{"menger_fold", {{"scale", 1, {3}, false, 1.000001, 1e6}, {"offset", 3, {1, 1, 1}}},
                                 always_conformal, false, menger_emit, menger_eval,
                                 "one Menger sponge step: octa_fold, scale about offset, folds the middle layer back", false,
                                 menger_dual};

}  // namespace sdfc::formula
