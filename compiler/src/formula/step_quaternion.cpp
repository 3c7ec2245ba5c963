// quaternion: q -> q^2 or q^3 with q = x + y i + z j + w k (z's three
// components and w; Mandelbulber's formula 5 and the built-in `julia:`).
// For q = (a, v): q^2 = (a^2 - v.v, 2a v), q^3 = (a (a^2 - 3 v.v), (3a^2 - v.v) v).
// The scalar derivative is the built-in's, 2|q| or 3|q|^2: |q dq + dq q| is
// at most 2|q||dq|, so it never underestimates the stretch of q^2.
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

// The 4x4 Jacobian (rows new x, y, z, w; columns x, y, z, w) as expressions
// of a = z.x, v = (z.y, z.z, w), vv = v.v.
std::array<std::string, 16> jacobian_text(bool cube) {
  const char* v[3] = {"z.y", "z.z", "zw"};
  std::array<std::string, 16> m;
  if (!cube) {
    m[0] = "2.0f * a";
    for (int i = 0; i < 3; ++i) {
      m[size_t(1 + i)] = fmt::format("-2.0f * {}", v[i]);
      m[size_t(4 * (i + 1))] = fmt::format("2.0f * {}", v[i]);
      m[size_t(5 * (i + 1))] = "2.0f * a";
    }
    return m;
  }
  m[0] = "3.0f * (a * a - vv)";
  for (int i = 0; i < 3; ++i) {
    m[size_t(1 + i)] = fmt::format("-6.0f * a * {}", v[i]);
    m[size_t(4 * (i + 1))] = fmt::format("6.0f * a * {}", v[i]);
    for (int j = 0; j < 3; ++j)
      m[size_t(4 * (i + 1) + 1 + j)] =
          fmt::format("-2.0f * {} * {}{}", v[i], v[j], i == j ? " + 3.0f * a * a - vv" : "");
  }
  return m;
}

void quaternion_emit(const Step& st, EmitState& s) {
  const bool cube = st.a[0] == 3;
  s.w.open(fmt::format("{{  // quaternion: q^{}", cube ? 3 : 2));
  s.w.line("const real a = z.x, vv = z.y * z.y + z.z * z.z + zw * zw;");
  if (s.jacobian)
    emit_rows4(s, jacobian_text(cube));
  else
    s.w.line(cube ? "dr = 3.0f * (a * a + vv) * dr;" : "dr = 2.0f * sqrt(a * a + vv) * dr;");
  s.w.line(cube ? "const real an = a * (a * a - 3.0f * vv), vs = 3.0f * a * a - vv;" : "const real an = a * a - vv, vs = 2.0f * a;");
  s.w.line("z = v3(an, z.y * vs, z.z * vs); zw = zw * vs;");
  s.w.close();
}

// f = 2|q| (grad 2 q / |q|) or 3|q|^2 (grad 6 q)
DualFactor quaternion_dual(const Step& st, EmitState&) {
  if (st.a[0] == 3) return {{}, "(3.0f * (v3_dot(z, z) + zw * zw))", "v3_scale(z, 6.0f)", "6.0f * zw"};
  return {{"const real q = fmax(sqrt(v3_dot(z, z) + zw * zw), K(1e-20f));"},
          "(2.0f * q)", "v3_scale(z, 2.0f / q)", "2.0f * zw / q"};
}
void quaternion_eval(const Step& st, RefState& s) {
  const bool cube = st.a[0] == 3;
  const double a = s.z[0], v[3] = {s.z[1], s.z[2], s.w}, vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  {  // the reference always carries the Jacobian
    std::array<double, 16> m{};
    m[0] = cube ? 3 * (a * a - vv) : 2 * a;
    for (int i = 0; i < 3; ++i) {
      m[size_t(1 + i)] = (cube ? -6 * a : -2) * v[i];
      m[size_t(4 * (i + 1))] = (cube ? 6 * a : 2) * v[i];
      for (int j = 0; j < 3; ++j)
        m[size_t(4 * (i + 1) + 1 + j)] = cube ? -2 * v[i] * v[j] + (i == j ? 3 * a * a - vv : 0) : (i == j ? 2 * a : 0);
    }
    apply_rows4(s, m);
  }
  s.dr *= cube ? 3 * (a * a + vv) : 2 * std::sqrt(a * a + vv);
  const double an = cube ? a * (a * a - 3 * vv) : a * a - vv, vs = cube ? 3 * a * a - vv : 2 * a;
  s.z = {an, v[0] * vs, v[1] * vs};
  s.w = v[2] * vs;
}

}  // namespace

extern const StepDef kQuaternion{"quaternion", {{"power", 1, {2}, false, 2, 3}}, always_conformal, true, quaternion_emit,
                                 quaternion_eval,
                                 "q -> q^power (2 or 3) for the quaternion x + y i + z j + w k; a 4-D step. Its scalar "
                                 "derivative 2|q| (3|q|^2) is the built-in julia's, a bound on the true stretch",
                                 true, quaternion_dual};

}  // namespace sdfc::formula
