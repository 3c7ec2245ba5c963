// triplex_newton: one Newton step for t^3 + c = 0 in Mandelbulber's triplex
// algebra, t -> 2/3 t - c * 1/(3 s t^2) (the heart of its Newton Pow3). Not
// conformal: the kernel carries its Jacobian forward through every
// intermediate (stdlib fold_newton3), the reference the same in double. A
// Newton step converges quadratically, so seen through an inversion about
// the root the orbit escapes like a square: a power step for the estimator.
#include <fmt/format.h>

#include <cmath>

#include "../codegen/code_writer.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

// Mandelbulber's fac_eff, to its ten digits.
constexpr double kTwoThirds = 0.6666666666;

bool never_conformal(const Step&) { return false; }

// sqrt(c.x^2 + c.y^2), and c.z over it as the product by c uses it (0 where
// the plane part is 0, so c on the z axis stays finite)
double plane_radius(const Step& st) { return std::hypot(st.a[0], st.a[1]); }
double z_over_plane(const Step& st) { return plane_radius(st) > 0 ? st.a[2] / plane_radius(st) : 0; }

void newton_emit(const Step& st, EmitState& s) {
  s.used.insert("fold_newton3");
  s.w.open("{  // triplex_newton: t -> 2/3 t - c / (3 s t^2)");
  s.w.line(fmt::format("vec3 g0, g1, g2; z = fold_newton3(z, {}, {}, {}, {}, {}, &g0, &g1, &g2);",
                       s.lit.vec3({st.a[0], st.a[1], st.a[2]}), s.lit.real(plane_radius(st)), s.lit.real(z_over_plane(st)),
                       s.lit.real(st.a[3]),
                       s.lit.real(kTwoThirds)));
  if (s.jacobian) {
    s.used.insert("v3_rows");
    s.w.line("ja = v3_rows(ja, g0, g1, g2); jb = v3_rows(jb, g0, g1, g2); jc = v3_rows(jc, g0, g1, g2);");
  } else {  // the Frobenius norm bounds the step's stretch
    s.w.line("dr = dr * sqrt(v3_dot(g0, g0) + v3_dot(g1, g1) + v3_dot(g2, g2));");
  }
  s.w.close();
}

void newton_eval(const Step& st, RefState& s) {
  const double cx = st.a[0], cy = st.a[1], cz = st.a[2], cr = plane_radius(st), hz = z_over_plane(st), sc = st.a[3];
  const double x = s.z[0], y = s.z[1], z = s.z[2];
  // the kernel's arithmetic, gradient beside value (see stdlib fold_newton3)
  auto add = [](V3 a, V3 b, double p = 1, double q = 1) { return V3{a[0] * p + b[0] * q, a[1] * p + b[1] * q, a[2] * p + b[2] * q}; };
  double q = std::max(x * x + y * y + z * z, 1e-30), k = 1 / (3 * sc * q * q);
  V3 gk{-4 * k / q * x, -4 * k / q * y, -4 * k / q * z};
  double rxy = std::max(x * x + y * y, 1e-30), sr = std::sqrt(rxy), h1 = 1 - z * z / rxy;
  V3 gh1{2 * x * z * z / (rxy * rxy), 2 * y * z * z / (rxy * rxy), -2 * z / rxy};
  double a = x * x - y * y, b = -2 * x * y;
  double tx = h1 * a * k, ty = h1 * b * k, tz = 2 * z * sr * k;
  V3 gtx = add(add(gh1, V3{2 * x, -2 * y, 0}, a * k, h1 * k), gk, 1, h1 * a);
  V3 gty = add(add(gh1, V3{-2 * y, -2 * x, 0}, b * k, h1 * k), gk, 1, h1 * b);
  V3 gtz = add(add(V3{0, 0, 2 * sr * k}, V3{x / sr, y / sr, 0}, 1, 2 * z * k), gk, 1, 2 * z * sr);
  double r2 = std::sqrt(std::max(tx * tx + ty * ty, 1e-30));
  V3 gr2 = add(gtx, gty, tx / r2, ty / r2);
  double h = 1 - hz * tz / r2;
  V3 gh = add(gtz, gr2, -hz / r2, hz * tz / (r2 * r2));
  double m = cx * tx - cy * ty, n = cy * tx + cx * ty;
  V3 gm = add(gtx, gty, cx, -cy), gn = add(gtx, gty, cy, cx);
  V3 g0 = add(V3{kTwoThirds, 0, 0}, add(gm, gh, h, m), 1, -1);
  V3 g1 = add(V3{0, kTwoThirds, 0}, add(gn, gh, h, n), 1, -1);
  V3 g2 = add(V3{0, 0, kTwoThirds}, add(gtz, gr2, cr, cz), 1, -1);
  apply_rows(s, {g0[0], g0[1], g0[2], g1[0], g1[1], g1[2], g2[0], g2[1], g2[2]});
  double frob = 0;
  for (const V3& g : {g0, g1, g2}) frob += g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  s.dr *= std::sqrt(frob);
  s.z = {kTwoThirds * x - m * h, kTwoThirds * y - n * h, kTwoThirds * z - (cr * tz + r2 * cz)};
}

}  // namespace

extern const StepDef kTriplexNewton{
    "triplex_newton",
    {{"c", 3, {-1, 0, 0}, false, -100, 100}, {"scale", 1, {1}, false, 1e-3, 1e3}},
    never_conformal,
    true,
    newton_emit,
    newton_eval,
    "one Newton step for t^3 + c = 0 in Mandelbulber's triplex algebra: t -> 2/3 t - c / (3 scale t^2) "
    "(Newton Pow3's core); not conformal (the chain runs the Jacobian)"};

}  // namespace sdfc::formula
