// The affine steps: rotate, scale (uniform, about an offset as in IFS),
// scale_xyz (non-conformal), translate and add_c.
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"
#include "sdfc/ir/fractal_math.hpp"

namespace sdfc::formula {

bool always_conformal(const Step&) { return true; }
DualFactor keeps_dr(const Step&, EmitState&) { return {}; }

void apply_rows(RefState& s, const std::array<double, 9>& m) {
  for (V3& c : s.j) c = {m[0] * c[0] + m[1] * c[1] + m[2] * c[2], m[3] * c[0] + m[4] * c[1] + m[5] * c[2],
                         m[6] * c[0] + m[7] * c[1] + m[8] * c[2]};
}

namespace {

void scale_columns(EmitState& s, const std::string& k) {
  s.w.line(fmt::format("ja = v3_mul(ja, {0}); jb = v3_mul(jb, {0}); jc = v3_mul(jc, {0});", k));
}

// ---- rotate: by `angle` degrees about `axis`
std::array<double, 9> rotation(const Step& st) {
  double l = std::sqrt(st.a[0] * st.a[0] + st.a[1] * st.a[1] + st.a[2] * st.a[2]);
  return ir::axis_rotation({st.a[0] / l, st.a[1] / l, st.a[2] / l}, st.a[3]);
}
void rotate_emit(const Step& st, EmitState& s) {
  auto m = rotation(st);
  std::string r0 = s.lit.vec3({m[0], m[1], m[2]}), r1 = s.lit.vec3({m[3], m[4], m[5]}), r2 = s.lit.vec3({m[6], m[7], m[8]});
  s.used.insert("v3_rows");
  s.w.line(fmt::format("z = v3_rows(z, {}, {}, {});  // rotate {} degrees", r0, r1, r2, st.a[3]));
  if (s.jacobian)
    s.w.line(fmt::format("ja = v3_rows(ja, {0}, {1}, {2}); jb = v3_rows(jb, {0}, {1}, {2}); jc = v3_rows(jc, {0}, {1}, {2});", r0,
                         r1, r2));
}
void rotate_eval(const Step& st, RefState& s) {
  auto m = rotation(st);
  V3 z = s.z;
  s.z = {m[0] * z[0] + m[1] * z[1] + m[2] * z[2], m[3] * z[0] + m[4] * z[1] + m[5] * z[2], m[6] * z[0] + m[7] * z[1] + m[8] * z[2]};
  apply_rows(s, m);
}

// ---- scale: z = s z - (s - 1) offset
void scale_emit(const Step& st, EmitState& s) {
  double k = st.a[0];
  V3 shift{st.a[1] * (k - 1), st.a[2] * (k - 1), st.a[3] * (k - 1)};
  if (shift == V3{0, 0, 0})
    s.w.line(fmt::format("z = v3_scale(z, {});  // scale", s.lit.real(k)));
  else
    s.w.line(fmt::format("z = v3_sub(v3_scale(z, {}), {});  // scale about the offset", s.lit.real(k), s.lit.vec3(shift)));
  if (s.jacobian)
    scale_columns(s, s.lit.vec3({k, k, k}));
  else
    s.w.line(fmt::format("dr = dr * {};", s.lit.real(std::fabs(k))));
}
DualFactor scale_dual(const Step& st, EmitState& s) { return {.f = s.lit.real(std::fabs(st.a[0]))}; }
void scale_eval(const Step& st, RefState& s) {
  double k = st.a[0];
  for (int i = 0; i < 3; ++i) s.z[i] = s.z[i] * k - st.a[1 + i] * (k - 1);
  for (V3& c : s.j)
    for (double& v : c) v *= k;
  s.dr *= std::fabs(k);
}

// ---- scale_xyz: a scale per axis. The scalar derivative (a `de:` override)
// takes the largest factor, which keeps r / dr on the safe side.
bool scale_xyz_conformal(const Step& st) {
  return std::fabs(st.a[0]) == std::fabs(st.a[1]) && std::fabs(st.a[1]) == std::fabs(st.a[2]);
}
void scale_xyz_emit(const Step& st, EmitState& s) {
  std::string k = s.lit.vec3({st.a[0], st.a[1], st.a[2]});
  s.w.line(fmt::format("z = v3_mul(z, {});  // scale_xyz", k));
  if (s.jacobian)
    scale_columns(s, k);
  else
    s.w.line(fmt::format("dr = dr * {};",
                         s.lit.real(std::max({std::fabs(st.a[0]), std::fabs(st.a[1]), std::fabs(st.a[2])}))));
}
DualFactor scale_xyz_dual(const Step& st, EmitState& s) {
  return {.f = s.lit.real(std::max({std::fabs(st.a[0]), std::fabs(st.a[1]), std::fabs(st.a[2])}))};
}
void scale_xyz_eval(const Step& st, RefState& s) {
  for (int i = 0; i < 3; ++i) s.z[i] *= st.a[i];
  for (V3& c : s.j)
    for (int i = 0; i < 3; ++i) c[i] *= st.a[i];
  s.dr *= std::max({std::fabs(st.a[0]), std::fabs(st.a[1]), std::fabs(st.a[2])});
}

// ---- translate
void translate_emit(const Step& st, EmitState& s) {
  s.w.line(fmt::format("z = v3_add(z, {});  // translate", s.lit.vec3({st.a[0], st.a[1], st.a[2]})));
}
void translate_eval(const Step& st, RefState& s) {
  for (int i = 0; i < 3; ++i) s.z[i] += st.a[i];
}

// ---- add_c: z + c, c = the point (dz/dp gains the identity) or julia's
// constant; in a 4-D chain w gains c's w (0 for the point: dw/dp is unchanged)
void add_c_emit(const Step&, EmitState& s) {
  s.w.line("z = v3_add(z, c);  // add_c");
  if (s.four_d) s.w.line("zw = zw + cw;");
  if (s.jacobian)
    s.w.line("ja.x += id; jb.y += id; jc.z += id;");
  else
    s.w.line("dr = dr + id;");
}
DualFactor add_c_dual(const Step&, EmitState&) { return {.adds = "id"}; }
void add_c_eval(const Step&, RefState& s) {
  for (int i = 0; i < 3; ++i) s.z[i] += s.c[i];
  s.w += s.cw;
  if (!s.mandel) return;
  for (int i = 0; i < 3; ++i) s.j[i][i] += 1;
  s.dr += 1;
}

}  // namespace

extern const StepDef kRotate{"rotate", {{"axis", 3, {0, 0, 1}}, {"angle", 1, {0}, true}}, always_conformal, false, rotate_emit,
                             rotate_eval, "rotates by angle degrees about axis", false, keeps_dr};
extern const StepDef kScale{"scale", {{"scale", 1, {2}, true}, {"offset", 3, {0, 0, 0}}}, always_conformal, false, scale_emit,
                            scale_eval, "z = scale z - (scale - 1) offset (IFS form; offset 0: a plain scale)", false,
                            scale_dual};
extern const StepDef kScaleXYZ{"scale_xyz", {{"scale", 3, {1, 1, 1}, true}}, scale_xyz_conformal, false, scale_xyz_emit,
                               scale_xyz_eval, "a scale per axis (non-conformal unless the three agree)", false, scale_xyz_dual};
extern const StepDef kTranslate{"translate", {{"offset", 3, {0, 0, 0}, true}}, always_conformal, false, translate_emit,
                                translate_eval, "adds offset to z", false, keeps_dr};
extern const StepDef kAddC{"add_c", {}, always_conformal, false, add_c_emit, add_c_eval,
                           "adds c: the point (Mandelbrot form) or the chain's julia constant", false, add_c_dual};

}  // namespace sdfc::formula
