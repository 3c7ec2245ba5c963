// mandelbox: Tom Lowe's box fold and sphere fold, z -> scale * fold(z) + c,
// with scale_xyz for a non-conformal (per-axis) scale.
#include <fmt/format.h>

#include "../frontend/animated_node.hpp"
#include "fractal.hpp"

SDFC_KIND(Mandelbox, 19, "mandelbox", Fractal, 0, "scale,min_radius,fixed_radius,folding_limit,iterations,julia,cx,cy,cz,sx,sy,sz,method", "de_mandelbox")

namespace sdfc::kinds {
namespace {
using frontend::MapReader;
using frontend::Param;
using frontend::Range;
using ir::DeMethod;

struct MandelboxP {
  double scale, min_radius, fixed_radius, folding_limit, iterations, julia;
  V3 c;     // the julia constant (julia != 0), else c = p
  V3 axis;  // scale_xyz: the scale's factor per axis
  double method;
};
constexpr size_t kScale = SDFC_AT(MandelboxP, scale), kFold = SDFC_AT(MandelboxP, folding_limit);

// A per-axis scale that is not the same on every axis.
bool non_conformal(const MandelboxP& b) { return b.axis[0] != b.axis[1] || b.axis[1] != b.axis[2]; }
bool jacobian(const MandelboxP& b) { return DeMethod(int(b.method)) == DeMethod::Jacobian; }

ir::NodeId lower(Lowering& l) {
  frontend::ValueReader& r = l.reader();
  std::string what = "mandelbox";
  MapReader m(r, l.body(), what, {"scale", "min_radius", "fixed_radius", "folding_limit", "iterations", "julia", "scale_xyz", "de"});
  double method = de_method(r, m, what, {DeMethod::Analytic, DeMethod::Jacobian});
  Param scale = mandelbox_scale(m, what, r);
  auto [min_r, fixed_r] = mandelbox_radii(m, what, r);
  double fl = m.number("folding_limit", 1.0, Range::positive(100));
  int iterations = m.integer("iterations", 12, 1, 200);
  bool julia = m.get("julia") != nullptr;
  frontend::Vec3d c = m.vec3("julia", {0, 0, 0}, Range::closed(-10, 10));
  frontend::Vec3d s = m.vec3("scale_xyz", {1, 1, 1}, Range::closed(0.25, 4));
  double smallest = std::min(std::fabs(scale.lo), std::fabs(scale.hi)) * std::min({s[0], s[1], s[2]});
  if (smallest <= 1.0 && m.get("scale_xyz")) {
    r.sink().error(m.get("scale_xyz")->loc,
                   fmt::format("mandelbox.scale_xyz: |scale| x the smallest factor is {:.3g}, but must be > 1", smallest),
                   "every axis must still expand; raise the smallest factor");
    s = {1, 1, 1};
  }
  return l.make_animated({scale, min_r, fixed_r, fl, double(iterations), julia ? 1.0 : 0.0, c[0], c[1], c[2], s[0],
                          s[1], s[2], method});
}

ir::Props props(const ir::Node& n) {
  auto b = view<MandelboxP>(n);
  double smallest = std::fabs(b.scale) * std::min({b.axis[0], b.axis[1], b.axis[2]});
  return estimate(ir::mandelbox_half_extent(smallest, b.folding_limit, orbit::len(b.c), b.julia != 0),
                  8 + b.iterations * (b.method == 0 ? 25 : 70));
}

// The arguments after p that the estimator and the trap function share.
std::string args(const Emitter& e) {
  auto b = view<MandelboxP>(e.n);
  return fmt::format("{}, {}, {}, {}, {}, {}, {}, {}", e.param(kScale), e.real(b.min_radius * b.min_radius),
                     e.real(b.fixed_radius * b.fixed_radius), e.param(kFold), int(b.iterations), int(b.julia),
                     e.vec3(b.c), e.vec3(b.axis));
}

std::string emit(Emitter& e) {
  return fmt::format("{}({}, {})", e.call(jacobian(view<MandelboxP>(e.n)) ? "de_mandelbox_jacobian" : "de_mandelbox"),
                     e.p, args(e));
}

std::string emit_orbit(Emitter& e) { return orbit_call(e, "trap_mandelbox", fmt::format("{}, {}", e.p, args(e)), true); }

std::string emit_dual(Emitter& e) {
  auto b = view<MandelboxP>(e.n);
  return fmt::format("{}({}, {}, {}, {}, {}, {}, {}, {}, {})", e.call("deg_mandelbox"), e.p, e.real(b.scale),
                     e.real(b.min_radius * b.min_radius), e.real(b.fixed_radius * b.fixed_radius),
                     e.real(b.folding_limit), int(b.iterations), int(b.julia), e.vec3(b.c), e.vec3(b.axis));
}

// The scalar derivative |z| / |dr|.
double analytic(const V3& p, const MandelboxP& b) {
  using orbit::dot;
  double scale = b.scale;
  int iterations = int(b.iterations);
  bool julia = b.julia != 0;
  V3 c = julia ? b.c : p, z = p;
  double dr = 1;
  for (int i = 0; i < iterations && dot(z, z) < 1e4; ++i) {
    double f = orbit::box_sphere_fold(z, b.folding_limit, b.min_radius, b.fixed_radius);
    for (int k = 0; k < 3; ++k) z[k] = scale * b.axis[k] * z[k] + c[k];
    dr = dr * std::fabs(scale) * f + (julia ? 0 : 1);
  }
  return orbit::len(z) / std::fabs(dr);
}

// de: jacobian: a full 3x3 Jacobian matrix product; |z| / ||J||.
double full_jacobian(const V3& p, const MandelboxP& b) {
  using orbit::dot;
  using M3 = std::array<double, 9>;  // row-major: J[i][j] = d z_i / d p_j
  auto matmul = [](const M3& x, const M3& y) {
    M3 r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) r[i * 3 + j] += x[i * 3 + k] * y[k * 3 + j];
    return r;
  };
  double scale = b.scale, fl = b.folding_limit, min2 = b.min_radius * b.min_radius;
  double fixed2 = b.fixed_radius * b.fixed_radius;
  int iterations = int(b.iterations);
  bool julia = b.julia != 0;
  V3 c = julia ? b.c : p, z = p;
  M3 J{1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int i = 0; i < iterations && dot(z, z) < 1e4; ++i) {
    // Each step's own Jacobian, multiplied onto the running one.
    M3 box{1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int k = 0; k < 3; ++k) {
      if (z[k] > fl) z[k] = 2 * fl - z[k], box[k * 4] = -1;
      else if (z[k] < -fl) z[k] = -2 * fl - z[k], box[k * 4] = -1;
    }
    J = matmul(box, J);
    double r2 = dot(z, z);
    M3 sphere{1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (r2 < min2) {
      for (int k = 0; k < 3; ++k) sphere[k * 4] = fixed2 / min2;
      for (double& v : z) v *= fixed2 / min2;
    } else if (r2 < fixed2) {
      double f = fixed2 / r2;  // d/dz (f2 z / |z|^2) = f (I - 2 z z^T / r2)
      for (int x = 0; x < 3; ++x)
        for (int y = 0; y < 3; ++y) sphere[x * 3 + y] = f * ((x == y ? 1 : 0) - 2 * z[x] * z[y] / r2);
      for (double& v : z) v *= f;
    }
    J = matmul(sphere, J);
    for (int x = 0; x < 3; ++x) {
      double m = scale * b.axis[x];
      z[x] = m * z[x] + c[x];
      for (int y = 0; y < 3; ++y) J[x * 3 + y] = m * J[x * 3 + y] + (!julia && x == y ? 1 : 0);
    }
  }
  // d = |z| / ||J||, with the Frobenius norm (>= the induced norm).
  double f2 = 0;
  for (double v : J) f2 += v * v;
  return orbit::len(z) / std::max(std::sqrt(f2), 1e-30);
}

double distance(const ir::Node& n, const V3& p) {
  auto b = view<MandelboxP>(n);
  return b.method != 0 ? full_jacobian(p, b) : analytic(p, b);
}

// The bounds search trusts the Jacobian estimator (a true bound) where the
// scalar one is known to overshoot: a per-axis scale.
double bounds_distance(const ir::Node& n, const V3& p) {
  auto b = view<MandelboxP>(n);
  if (b.method == 0 && (b.axis[0] != 1 || b.axis[1] != 1 || b.axis[2] != 1)) return full_jacobian(p, b);
  return distance(n, p);
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  auto b = view<MandelboxP>(n);
  int iterations = int(b.iterations), k = 0;
  double trap = 1e10;
  V3 c = b.julia != 0 ? b.c : p, z = p;
  for (; k < iterations && orbit::dot(z, z) < 1e4; ++k) {
    orbit::box_sphere_fold(z, b.folding_limit, b.min_radius, b.fixed_radius);
    for (int i = 0; i < 3; ++i) z[i] = b.scale * b.axis[i] * z[i] + c[i];
    trap = std::min(trap, orbit::measure(shape, z));
  }
  return {trap, orbit::smooth_iteration(k, orbit::len(z), 100, std::fabs(b.scale), false, iterations)};
}

std::string de_summary(const ir::Node& n) {
  auto b = view<MandelboxP>(n);
  if (non_conformal(b) && DeMethod(int(b.method)) == DeMethod::Analytic)
    return "de: analytic, unknown (non-conformal: the scalar derivative can overshoot; use de: jacobian)";
  return de_words(DeMethod(int(b.method)));
}

// See ir::default_step_factor: |z| / dr overshoots the conformal set by about 1.5 %.
double step_factor(const ir::Node& n) {
  auto b = view<MandelboxP>(n);
  return DeMethod(int(b.method)) == DeMethod::Analytic && !non_conformal(b) ? 0.9 : 1.0;
}

static constexpr ParamDoc k_docs[] = {
    {"scale", "number", "-1.5", "-8 to 8, |scale| > 1", "the expansion per step: -1.5 and 2 are the classic boxes"},
    {"min_radius", "number", "0.5", "> 0, less than fixed_radius", "inside it the sphere fold scales by a constant"},
    {"fixed_radius", "number", "1", "> 0, up to 100", "the sphere fold's radius"},
    {"folding_limit", "number", "1", "> 0, up to 100", "where the box fold reflects"},
    {"iterations", "integer", "12", "1 to 200", "orbit steps: more gives finer detail"},
    {"julia", "vec3", "", "each -10 to 10", "a fixed c instead of the point (a Julia Mandelbox)"},
    {"scale_xyz", "vec3", "[1, 1, 1]", "each 0.25 to 4; |scale| x the smallest > 1",
     "a factor of the scale per axis (non-conformal: use de: jacobian)"},
    {"de", "one of analytic|jacobian", "analytic", "", "the distance estimator (jacobian: the full matrix, a true bound)"},
};

}  // namespace

namespace described {
extern const Description Mandelbox{
    .kind = ir::Kind::Mandelbox, .yaml = "mandelbox", .example = "{mandelbox: {scale: -1.5, iterations: 12}}",
    .param_count = count_of<MandelboxP>(), .lower = lower, .props = props, .call_args = {}, .distance = distance,
    .dual_normals = true, .emit = emit, .emit_orbit = emit_orbit, .emit_dual = emit_dual, .orbit_colour = orbit_colour,
    .de_summary = de_summary, .step_factor = step_factor, .bounds_trust = 0.5, .bounds_distance = bounds_distance,
    .escape_time = true, .summary = "an estimate (a bound in practice, not proven)", .docs = k_docs};
}

}  // namespace sdfc::kinds
