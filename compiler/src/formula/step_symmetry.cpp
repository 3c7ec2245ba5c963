// Symmetry folds made of reflections: polyfold (the dihedral fold of order
// n about the z axis) and icosa_fold (the icosahedron's planes, as in the
// kaleidoscopic IFS). Reflections and rotations keep |dz|: conformal, the
// scalar derivative unchanged, the Jacobian's columns moved with z.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

// ---- polyfold: rotate z.xy into the sector |angle| <= pi / order, then y = |y|
void poly_emit(const Step& st, EmitState& s) {
  const double sector = 2 * std::numbers::pi / st.a[0];
  s.w.open(fmt::format("{{  // polyfold order {}", st.a[0]));
  s.w.line(fmt::format("real t = floor(atan2(z.y, z.x) * {} + 0.5f) * {};", s.lit.real(1 / sector), s.lit.real(sector)));
  s.w.line("real cs = cos(t), sn = sin(t);");
  const char* vs[4] = {"z", "ja", "jb", "jc"};
  for (int i = 0; i < (s.jacobian ? 4 : 1); ++i)
    s.w.line(fmt::format("{0} = v3(cs * {0}.x + sn * {0}.y, cs * {0}.y - sn * {0}.x, {0}.z);", vs[i]));
  if (s.jacobian) s.w.line("{ real sg = SEL((real)(1.0f), (real)(-1.0f), z.y < 0.0f); ja.y *= sg; jb.y *= sg; jc.y *= sg; }");
  s.w.line("z.y = fabs(z.y);");
  s.w.close();
}
void poly_eval(const Step& st, RefState& s) {
  const double sector = 2 * std::numbers::pi / st.a[0];
  double t = std::floor(std::atan2(s.z[1], s.z[0]) / sector + 0.5) * sector, cs = std::cos(t), sn = std::sin(t);
  auto turn = [&](V3& v) { v = {cs * v[0] + sn * v[1], cs * v[1] - sn * v[0], v[2]}; };
  turn(s.z);
  for (V3& c : s.j) turn(c);
  if (s.z[1] < 0) {
    s.z[1] = -s.z[1];
    for (V3& c : s.j) c[1] = -c[1];
  }
}

// ---- icosa_fold: abs, then reflections in the planes n1, n2 of the
// icosahedral group (golden-ratio normals), repeated so every point lands in
// one fundamental cell
constexpr double kPhi = std::numbers::phi;
V3 unit(V3 v) {
  double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
const V3 kN1 = unit({-kPhi, kPhi - 1, 1}), kN2 = unit({1, -kPhi, kPhi + 1});
// 0: abs, 1: reflect in n1 where z.n1 > 0, 2: the same in n2
constexpr int kIcosa[] = {0, 2, 0, 1, 2, 0, 1};

void icosa_emit(const Step&, EmitState& s) {
  const std::string n1 = s.lit.vec3(kN1), n2 = s.lit.vec3(kN2);
  if (s.jacobian) s.used.insert("fold_reflect_j");
  s.w.open("{  // icosa_fold");
  for (int op : kIcosa) {
    if (op == 0) {
      if (s.jacobian) {
        s.w.line("fold_reflect_j(&z, &ja, &jb, &jc, v3(1.0f, 0.0f, 0.0f), z.x < 0.0f);");
        s.w.line("fold_reflect_j(&z, &ja, &jb, &jc, v3(0.0f, 1.0f, 0.0f), z.y < 0.0f);");
        s.w.line("fold_reflect_j(&z, &ja, &jb, &jc, v3(0.0f, 0.0f, 1.0f), z.z < 0.0f);");
      } else {
        s.w.line("z = v3(fabs(z.x), fabs(z.y), fabs(z.z));");
      }
      continue;
    }
    const std::string& n = op == 1 ? n1 : n2;
    if (s.jacobian)
      s.w.line(fmt::format("fold_reflect_j(&z, &ja, &jb, &jc, {0}, v3_dot(z, {0}) > 0.0f);", n));
    else
      s.w.line(fmt::format("z = v3_mad(z, {0}, -2.0f * fmax(v3_dot(z, {0}), K(0.0f)));", n));
  }
  s.w.close();
}
void reflect_where(RefState& s, const V3& n, bool on) {
  if (!on) return;
  auto r = [&](V3& v) {
    double t = 2 * (v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
    for (int k = 0; k < 3; ++k) v[k] -= t * n[k];
  };
  r(s.z);
  for (V3& c : s.j) r(c);
}
void icosa_eval(const Step&, RefState& s) {
  for (int op : kIcosa) {
    if (op == 0) {
      reflect_where(s, {1, 0, 0}, s.z[0] < 0);
      reflect_where(s, {0, 1, 0}, s.z[1] < 0);
      reflect_where(s, {0, 0, 1}, s.z[2] < 0);
      continue;
    }
    const V3& n = op == 1 ? kN1 : kN2;
    reflect_where(s, n, s.z[0] * n[0] + s.z[1] * n[1] + s.z[2] * n[2] > 0);
  }
}

}  // namespace

extern const StepDef kPolyfold{"polyfold", {{"order", 1, {3}, false, 1, 64}}, always_conformal, false, poly_emit, poly_eval,
                               "folds z.xy into one sector of angle 360/order degrees about the z axis, mirrored",
                               false, keeps_dr};
extern const StepDef kIcosaFold{"icosa_fold", {}, always_conformal, false, icosa_emit, icosa_eval,
                                "the icosahedron's symmetry: abs and reflections in its golden-ratio planes", false,
                                keeps_dr};

}  // namespace sdfc::formula
