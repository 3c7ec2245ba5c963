// Aexion's quadray sets (Mandelbulber's formula 19): z's projections on the
// four axes of a tetrahedron make a 4-D z (quadray, on the first iteration),
// then each iteration squares it in Aexion's way and adds c's own quadray
// form. The projections' rows s_k satisfy sum s_k s_k^T = 4 I, so quadray
// stretches every direction by exactly 2 (conformal); the square is not.
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

// The tetrahedron's axes, one row per new component.
constexpr int kAxis[4][3] = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};

double sgn(double x) { return double((x > 0) - (x < 0)); }

std::string projection(const char* x, const char* y, const char* z, int k) {
  auto term = [](int s, const char* v, bool first) { return fmt::format("{}{}", s < 0 ? "-" : first ? "" : "+", v); };
  return term(kAxis[k][0], x, true) + term(kAxis[k][1], y, false) + term(kAxis[k][2], z, false);
}

// ---- quadray: z -> (|x + y + z|, |-x - y + z|, |-x + y - z|, |x - y - z|) + cadd
void quadray_emit(const Step& st, EmitState& s) {
  const std::string add = s.lit.real(st.a[0]);
  s.w.open("{  // quadray: z's projections on the tetrahedron's axes, plus cadd");
  s.w.line(fmt::format("const real q0 = {}, q1 = {}, q2 = {}, q3 = {};", projection("z.x", "z.y", "z.z", 0),
                       projection("z.x", "z.y", "z.z", 1), projection("z.x", "z.y", "z.z", 2), projection("z.x", "z.y", "z.z", 3)));
  if (s.jacobian) {
    std::array<std::string, 16> m;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 3; ++j) m[size_t(4 * k + j)] = fmt::format("{}sign(q{})", kAxis[k][j] < 0 ? "-" : "", k);
    emit_rows4(s, m);
  } else {
    s.w.line("dr = 2.0f * dr;");
  }
  s.w.line(fmt::format("z = v3(fabs(q0) + {0}, fabs(q1) + {0}, fabs(q2) + {0}); zw = fabs(q3) + {0};", add));
  s.w.close();
}

DualFactor quadray_dual(const Step&, EmitState&) { return {.f = "2.0f"}; }
void quadray_eval(const Step& st, RefState& s) {
  double q[4];
  for (int k = 0; k < 4; ++k) q[k] = kAxis[k][0] * s.z[0] + kAxis[k][1] * s.z[1] + kAxis[k][2] * s.z[2];
  {  // the reference always carries the Jacobian
    std::array<double, 16> m{};
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 3; ++j) m[size_t(4 * k + j)] = kAxis[k][j] * sgn(q[k]);
    apply_rows4(s, m);
  }
  s.dr *= 2;
  s.z = {std::fabs(q[0]) + st.a[0], std::fabs(q[1]) + st.a[0], std::fabs(q[2]) + st.a[0]};
  s.w = std::fabs(q[3]) + st.a[0];
}

// ---- aexion: (x² - y² + 2wz, y² - x² + 2wz, z² - w² + 2xy, w² - z² + 2xy) + quadray(c) + cadd
bool never_conformal(const Step&) { return false; }

// Rows new x, y, z, w over x, y, z, w, as (sign, component) of 2 * component.
constexpr int kSign[16] = {1, -1, 1, 1, -1, 1, 1, 1, 1, 1, 1, -1, 1, 1, -1, 1};
constexpr int kComp[16] = {0, 1, 3, 2, 0, 1, 3, 2, 1, 0, 2, 3, 1, 0, 2, 3};

void aexion_emit(const Step& st, EmitState& s) {
  static const char* const names[4] = {"z.x", "z.y", "z.z", "zw"};
  const std::string add = s.lit.real(st.a[0]);
  s.w.open("{  // aexion: the quadray square, plus c's quadray form");
  s.w.line(fmt::format("const real k0 = {}, k1 = {}, k2 = {}, k3 = {};", projection("c.x", "c.y", "c.z", 0),
                       projection("c.x", "c.y", "c.z", 1), projection("c.x", "c.y", "c.z", 2), projection("c.x", "c.y", "c.z", 3)));
  if (s.jacobian) {
    std::array<std::string, 16> m;
    for (size_t k = 0; k < 16; ++k) m[k] = fmt::format("{}2.0f * {}", kSign[k] < 0 ? "-" : "", names[kComp[k]]);
    emit_rows4(s, m);
    // c's quadray form moves with the point: its rows are sign(k) times the axes
    s.w.line("const real g0 = id * sign(k0), g1 = id * sign(k1), g2 = id * sign(k2), g3 = id * sign(k3);");
    const char* cols[3][2] = {{"ja", "jw.x"}, {"jb", "jw.y"}, {"jc", "jw.z"}};
    for (int j = 0; j < 3; ++j)
      s.w.line(fmt::format("{0} = v3_add({0}, v3({2}g0, {3}g1, {4}g2)); {1} = {1} {5} g3;", cols[j][0], cols[j][1],
                           kAxis[0][j] < 0 ? "-" : "", kAxis[1][j] < 0 ? "-" : "", kAxis[2][j] < 0 ? "-" : "",
                           kAxis[3][j] < 0 ? "-" : "+"));
  } else {
    s.w.line("dr = 2.0f * sqrt(v3_dot(z, z) + zw * zw) * dr + 2.0f * id;");
  }
  s.w.line("const real x = z.x, y = z.y, t = z.z;");
  s.w.line(fmt::format("z = v3(x * x - y * y + 2.0f * zw * t + fabs(k0) + {0}, y * y - x * x + 2.0f * zw * t + fabs(k1) + {0},"
                       " t * t - zw * zw + 2.0f * x * y + fabs(k2) + {0});",
                       add));
  s.w.line(fmt::format("zw = zw * zw - t * t + 2.0f * x * y + fabs(k3) + {};", add));
  s.w.close();
}

// f = 2|q| (grad 2 q / |q|), and 2 id added: the scalar estimate of a `de:` override
DualFactor aexion_dual(const Step&, EmitState&) {
  return {{"const real q = fmax(sqrt(v3_dot(z, z) + zw * zw), K(1e-20f));"},
          "(2.0f * q)", "v3_scale(z, 2.0f / q)", "2.0f * zw / q", "2.0f * id"};
}
void aexion_eval(const Step& st, RefState& s) {
  const double q[4] = {s.z[0], s.z[1], s.z[2], s.w};
  double k[4];
  for (int i = 0; i < 4; ++i) k[i] = kAxis[i][0] * s.c[0] + kAxis[i][1] * s.c[1] + kAxis[i][2] * s.c[2];
  {  // the reference always carries the Jacobian
    std::array<double, 16> m;
    for (size_t i = 0; i < 16; ++i) m[i] = 2 * kSign[i] * q[kComp[i]];
    apply_rows4(s, m);
    if (s.mandel)
      for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) s.j[size_t(j)][size_t(i)] += kAxis[i][j] * sgn(k[i]);
        s.jw[size_t(j)] += kAxis[3][j] * sgn(k[3]);
      }
  }
  s.dr = 2 * std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) * s.dr + (s.mandel ? 2 : 0);
  const double a = st.a[0];
  s.z = {q[0] * q[0] - q[1] * q[1] + 2 * q[3] * q[2] + std::fabs(k[0]) + a,
         q[1] * q[1] - q[0] * q[0] + 2 * q[3] * q[2] + std::fabs(k[1]) + a,
         q[2] * q[2] - q[3] * q[3] + 2 * q[0] * q[1] + std::fabs(k[2]) + a};
  s.w = q[3] * q[3] - q[2] * q[2] + 2 * q[0] * q[1] + std::fabs(k[3]) + a;
}

}  // namespace

extern const StepDef kQuadray{"quadray", {{"cadd", 1, {0}, false, -100, 100}}, always_conformal, false, quadray_emit,
                              quadray_eval,
                              "z to a 4-D z: its projections on the tetrahedron's four axes, made positive, plus cadd "
                              "(Aexion's first iteration); a 4-D step, conformal with factor 2",
                              true, quadray_dual};
extern const StepDef kAexion{"aexion", {{"cadd", 1, {0}, false, -100, 100}}, never_conformal, true, aexion_emit, aexion_eval,
                             "Aexion's square of the 4-D z plus c's quadray form (|cx + cy + cz| + cadd, ...) in place "
                             "of add_c; a 4-D step, not conformal (the chain runs the Jacobian)",
                             true, aexion_dual};

}  // namespace sdfc::formula
