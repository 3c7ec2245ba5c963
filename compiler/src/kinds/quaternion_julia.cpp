// julia: the quaternion Julia set, q -> q^degree + c, sliced at k = slice.
#include <fmt/format.h>

#include "fractal.hpp"

SDFC_KIND(QuaternionJulia, 20, "julia", Fractal, 0, "ca,cb,cc,cd,degree,iterations,slice,bailout", "de_quaternion_julia")

namespace sdfc::kinds {
namespace {
using frontend::Range;

struct QuaternionJuliaP {
  std::array<double, 4> c;  // w + x i + y j + z k
  double degree, iterations, slice, bailout;
};
constexpr size_t kCw = SDFC_AT(QuaternionJuliaP, c), kSlice = SDFC_AT(QuaternionJuliaP, slice),
                 kBailout = SDFC_AT(QuaternionJuliaP, bailout);

double c_norm(const QuaternionJuliaP& j) {
  return std::sqrt(j.c[0] * j.c[0] + j.c[1] * j.c[1] + j.c[2] * j.c[2] + j.c[3] * j.c[3]);
}

ir::NodeId lower(Lowering& l) {
  frontend::ValueReader& r = l.reader();
  frontend::MapReader m(r, l.body(), "julia", {"c", "degree", "iterations", "slice", "bailout", "de"});
  de_method(r, m, "julia", {ir::DeMethod::Analytic});
  std::vector<double> c = {-0.2, 0.6, 0.2, 0.2};
  if (const SourceValue* cv = m.get("c")) c = r.vecn(*cv, "julia.c", 4, Range::closed(-4, 4));
  int degree = m.integer("degree", 2, 2, 3);
  int iterations = m.integer("iterations", 12, 1, 1000);
  double slice = m.number("slice", 0.0, Range::closed(-4, 4));
  double bailout = m.number("bailout", 4.0, {1, 1e3, true});
  return l.make(QuaternionJuliaP{{c[0], c[1], c[2], c[3]}, double(degree), double(iterations), slice, bailout});
}

ir::Props props(const ir::Node& n) {
  auto j = view<QuaternionJuliaP>(n);
  return estimate(ir::julia_set_radius(j.degree, c_norm(j)), 10 + j.iterations * (j.degree == 3 ? 22 : 16));
}

// The arguments after p that the estimator and the trap function share.
std::string args(const Emitter& e) {
  auto j = view<QuaternionJuliaP>(e.n);
  return fmt::format("{}, {}, {}, {}, {}, {}", e.param(kSlice), e.param(kCw), e.vec3({j.c[1], j.c[2], j.c[3]}),
                     int(j.degree), int(j.iterations), e.param(kBailout));
}

std::string emit(Emitter& e) {
  auto j = view<QuaternionJuliaP>(e.n);
  return fmt::format("{}({}, {}, {})", e.call("de_quaternion_julia"), e.p, args(e),
                     e.real(ir::julia_set_radius(j.degree, c_norm(j))));
}

std::string emit_orbit(Emitter& e) {
  return orbit_call(e, "trap_quaternion_julia", fmt::format("{}, {}", e.p, args(e)), true);
}

std::string emit_dual(Emitter& e) {
  auto j = view<QuaternionJuliaP>(e.n);
  return fmt::format("{}({}, {}, {}, {}, {}, {}, {})", e.call("deg_quaternion_julia"), e.p, e.real(j.slice),
                     e.real(j.c[0]), e.vec3({j.c[1], j.c[2], j.c[3]}), int(j.degree), int(j.iterations),
                     e.real(j.bailout));
}

struct Quat {
  double w, x, y, z;
};
Quat qmul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
double qnorm(const Quat& a) { return std::sqrt(a.w * a.w + a.x * a.x + a.y * a.y + a.z * a.z); }

double distance(const ir::Node& n, const V3& p) {
  auto j = view<QuaternionJuliaP>(n);
  Quat c{j.c[0], j.c[1], j.c[2], j.c[3]}, z{p[0], p[1], p[2], j.slice};
  int degree = int(j.degree), iterations = int(j.iterations);
  double bailout = j.bailout, md = 1, r = qnorm(z);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    md = degree * std::pow(r, degree - 1) * md;
    Quat zn = qmul(z, z);
    if (degree == 3) zn = qmul(zn, z);
    z = {zn.w + c.w, zn.x + c.x, zn.y + c.y, zn.z + c.z};
    r = qnorm(z);
  }
  double radius = ir::julia_set_radius(degree, qnorm(c));
  double r0 = std::sqrt(orbit::dot(p, p) + j.slice * j.slice);
  if (r0 > 1.5 * radius) return r0 - radius;
  return 0.5 * std::log(std::max(r, 1e-20)) * r / md;
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  using orbit::dot;
  auto j = view<QuaternionJuliaP>(n);
  // q = a + v (v = (i, j, k) parts); the point is x + y i + z j + slice k.
  double a = p[0], bailout = j.bailout, trap = 1e10;
  V3 v{p[1], p[2], j.slice};
  int degree = int(j.degree), iterations = int(j.iterations), k = 0;
  auto r = [&] { return std::sqrt(a * a + dot(v, v)); };
  for (; k < iterations && r() < bailout; ++k) {
    double vv = dot(v, v);
    double an = degree == 3 ? a * (a * a - 3 * vv) : a * a - vv, vs = degree == 3 ? 3 * a * a - vv : 2 * a;
    for (int i = 0; i < 3; ++i) v[i] = v[i] * vs + j.c[1 + i];
    a = an + j.c[0];
    trap = std::min(trap, orbit::measure(shape, V3{a, v[0], v[1]}));
  }
  return {trap, orbit::smooth_iteration(k, r(), bailout, degree, true, iterations)};
}

std::string de_summary(const ir::Node&) { return de_words(ir::DeMethod::Analytic); }

static constexpr ParamDoc k_docs[] = {
    {"c", "list of 4 numbers", "[-0.2, 0.6, 0.2, 0.2]", "each -4 to 4", "the quaternion constant w, x, y, z"},
    {"degree", "integer", "2", "2 to 3", "the power of q -> q^degree + c"},
    {"iterations", "integer", "12", "1 to 1000", "orbit steps: more gives finer detail"},
    {"slice", "number", "0", "-4 to 4", "the k coordinate of the 3D slice through the 4D set"},
    {"bailout", "number", "4", "> 1, up to 1000", "the radius past which an orbit has escaped"},
    {"de", "one of analytic", "analytic", "", "the distance estimator"},
};

}  // namespace

namespace described {
extern const Description QuaternionJulia{
    .kind = ir::Kind::QuaternionJulia, .yaml = "julia", .example = "{julia: {c: [-0.2, 0.6, 0.2, 0.2]}}",
    .param_count = count_of<QuaternionJuliaP>(), .lower = lower, .props = props, .call_args = {},
    .distance = distance, .dual_normals = true, .emit = emit, .emit_orbit = emit_orbit, .emit_dual = emit_dual,
    .orbit_colour = orbit_colour, .de_summary = de_summary, .bounds_trust = 0.5,
    .escape_time = true, .summary = "an estimate (a bound in practice, not proven)", .docs = k_docs};
}

}  // namespace sdfc::kinds
