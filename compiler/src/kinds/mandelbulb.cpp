// mandelbulb: White and Nylander's power in spherical coordinates, z -> z^power + p.
#include <fmt/format.h>

#include "../frontend/animated_node.hpp"
#include "fractal.hpp"

SDFC_KIND(Mandelbulb, 6, "mandelbulb", Fractal, 0, "power,iterations,bailout,method", "de_mandelbulb")

namespace sdfc::kinds {
namespace {
using frontend::Param;
using frontend::Range;
using ir::DeMethod;

struct MandelbulbP {
  double power, iterations, bailout, method;
};
constexpr size_t kPower = SDFC_AT(MandelbulbP, power), kBailout = SDFC_AT(MandelbulbP, bailout);

ir::Props props(const ir::Node& n) {
  // The estimator is a bound in practice but not provably; L = 1 assumed.
  // The numeric methods run the orbit four times.
  auto b = view<MandelbulbP>(n);
  return estimate(ir::mandelbulb_set_radius(b.power), (10 + b.iterations * 45) * (b.method == 0 ? 1 : 4));
}

std::string emit(Emitter& e) {
  const ir::Node& n = e.n;
  auto b = view<MandelbulbP>(n);
  std::string radius = e.real(ir::mandelbulb_set_radius(b.power));
  // An animated power takes the trig formula (the trig-free one is
  // specialised to one whole power) and the radius of its set per frame,
  // as ir::mandelbulb_set_radius computes it.
  if (n.animation(kPower))
    radius = fmt::format("({0} <= {1} ? {2} : fmin({2}, pow({3}, {4} / ({0} - {4}))))", e.param(kPower), e.real(1.25),
                         e.real(4.0), e.real(2.0), e.real(1.0));
  int ipower = integer_power(b.power) && !n.animation(kPower) ? int(b.power) : 0;  // > 0: the trig-free power
  auto method = DeMethod(int(b.method));
  if (method != DeMethod::Analytic)
    return fmt::format("{}({}, {}, {}, {}, {}, {}, {})  /* de: {} */", e.call("de_mandelbulb_numeric"), e.p,
                       e.param(kPower), ipower, int(b.iterations), e.param(kBailout), radius, int(b.method),
                       ir::de_method_name(method));
  if (ipower)  // trig-free: the angles' multiples come from complex powers
    return fmt::format("{}({}, {}, {}, {}, {}, 0, v3_splat(0.0f))", e.call("de_mandelbulb_int"), e.p, ipower,
                       int(b.iterations), bulb_estimator_radius(e, kPower, kBailout), radius);
  return fmt::format("{}({}, {}, {}, {}, {})", e.call("de_mandelbulb"), e.p, e.param(kPower), int(b.iterations),
                     bulb_estimator_radius(e, kPower, kBailout), radius);
}

std::string emit_orbit(Emitter& e) {
  auto b = view<MandelbulbP>(e.n);
  // Trig-free like the distance; the iterations AOV keeps the trig orbit,
  // whose rounding (and so escape step) it has always had.
  if (integer_power(b.power) && !e.n.animation(kPower) && e.value != codegen::detail::OrbitValue::Escape)
    return orbit_call(e, "trap_mandelbulb_int",
                      fmt::format("{}, {}, {}, {}, {}, {}", e.p, int(b.power), int(b.iterations), e.param(kBailout), 0,
                                  "v3_splat(0.0f)"),
                      true);
  return orbit_call(e, "trap_mandelbulb",
                    fmt::format("{}, {}, {}, {}, {}, {}", e.p, e.param(kPower), int(b.iterations), e.param(kBailout), 0,
                                "v3_splat(0.0f)"),
                    true);
}

std::string emit_dual(Emitter& e) {
  auto b = view<MandelbulbP>(e.n);
  return fmt::format("{}({}, {}, {}, {}, 0, v3_splat(0.0f))", e.call("deg_mandelbulb"), e.p, e.real(b.power),
                     int(b.iterations), bulb_estimator_radius(e, kPower, kBailout));
}

double analytic(const V3& p, double power, int iterations, double bailout) {
  bailout = ir::bulb_estimator_radius(power, bailout);
  double zx = p[0], zy = p[1], zz = p[2];
  auto len = [](double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); };
  double dr = 1.0, r = len(zx, zy, zz);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    double rs = std::max(r, 1e-20);
    double theta = std::acos(std::clamp(zz / rs, -1.0, 1.0)) * power;
    double phi = std::atan2(zy, zx) * power;
    double rp = std::pow(rs, power - 1.0);
    dr = rp * power * dr + 1.0;
    double zr = rp * rs;
    zx = zr * std::sin(theta) * std::cos(phi) + p[0];
    zy = zr * std::sin(theta) * std::sin(phi) + p[1];
    zz = zr * std::cos(theta) + p[2];
    r = len(zx, zy, zz);
  }
  double r0 = len(p[0], p[1], p[2]);
  double set_radius = ir::mandelbulb_set_radius(power);
  // Far field: distance to the ball that holds the set (the estimator overshoots there).
  if (r0 > 1.5 * set_radius) return r0 - set_radius;
  return 0.5 * std::log(std::max(r, 1e-20)) * r / dr;
}

// de: gradient / potential / sinh: four orbits, forward differences.
double numeric(const V3& p, const MandelbulbP& b) {
  using orbit::len;
  double power = b.power, bailout = b.bailout;
  int iterations = int(b.iterations);
  auto method = DeMethod(int(b.method));
  // |z| after passing the bailout, or after exactly `pin` steps.
  auto run = [&](const V3& c, int pin, int* steps) {
    V3 z = c;
    int n = 0;
    while (n < iterations && (pin >= 0 ? n < pin : len(z) < bailout)) {
      double rp;
      V3 zn = orbit::bulb_power(z, power, &rp);
      for (int k = 0; k < 3; ++k) z[k] = zn[k] + c[k];
      ++n;
    }
    *steps = n;
    return len(z);
  };
  const double eps = 1e-4;
  int n, nx, ny, nz;
  double r = run(p, -1, &n);
  int pin = method == DeMethod::Gradient ? n : -1;
  double rx = run({p[0] + eps, p[1], p[2]}, pin, &nx);
  double ry = run({p[0], p[1] + eps, p[2]}, pin, &ny);
  double rz = run({p[0], p[1], p[2] + eps}, pin, &nz);
  double de;
  if (method == DeMethod::Gradient) {
    double g = len({rx - r, ry - r, rz - r}) / eps;
    de = 0.5 * r * std::log(std::max(r, 1e-20)) / std::max(g, 1e-20);
  } else {
    auto G = [&](double rr, int k) { return std::log(std::max(rr, 1e-20)) / std::pow(power, k); };
    double g0 = G(r, n);
    double g = std::max(len({G(rx, nx) - g0, G(ry, ny) - g0, G(rz, nz) - g0}) / eps, 1e-20);
    de = method == DeMethod::Potential ? 0.5 * g0 / g : 0.5 * std::sinh(g0) / (std::exp(g0) * g);
  }
  if (r < bailout) de = 0;  // never escaped: inside
  double radius = ir::mandelbulb_set_radius(power);
  double r0 = len(p);
  return r0 > 1.5 * radius ? r0 - radius : de;
}

double distance(const ir::Node& n, const V3& p) {
  auto b = view<MandelbulbP>(n);
  if (b.method != 0) return numeric(p, b);
  return analytic(p, b.power, int(b.iterations), b.bailout);
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  auto b = view<MandelbulbP>(n);
  int iterations = int(b.iterations), k = 0;
  double trap = 1e10;
  V3 z = p;
  for (; k < iterations && orbit::len(z) < b.bailout; ++k) {
    V3 w = orbit::bulb(z, b.power);
    for (int i = 0; i < 3; ++i) z[i] = w[i] + p[i];
    trap = std::min(trap, orbit::measure(shape, z));
  }
  return {trap, orbit::smooth_iteration(k, orbit::len(z), b.bailout, b.power, true, iterations)};
}

std::string de_summary(const ir::Node& n) { return de_words(DeMethod(int(view<MandelbulbP>(n).method))); }

static constexpr ParamDoc k_docs[] = {
    {"power", "number", "8", "1 to 64", "the exponent of z -> z^power + p; 8 gives the classic bulb"},
    {"iterations", "integer", "10", "1 to 1000", "orbit steps: more gives finer detail"},
    {"bailout", "number", "2", "> 0, up to 1000", "the radius past which an orbit has escaped"},
    {"julia", "vec3", "", "each -4 to 4", "makes it a Juliabulb: z -> z^power + julia (power >= 2, not animated)"},
    {"de", "one of analytic|gradient|potential|sinh", "analytic", "",
     "the distance estimator (with julia: analytic only)"},
};

}  // namespace

ir::NodeId lower_mandelbulb(Lowering& l) {
  frontend::ValueReader& r = l.reader();
  const SourceLoc& at = l.at();
  frontend::MapReader m(r, l.body(), "mandelbulb", {"power", "iterations", "bailout", "julia", "de"});
  Param power = m.param("power", 8.0, Range::closed(1, 64));
  int iterations = m.integer("iterations", 10, 1, 1000);
  Param bailout = m.param("bailout", 2.0, {0, 1e3, true});
  if (!m.get("julia")) {
    double method = de_method(r, m, "mandelbulb", {DeMethod::Analytic, DeMethod::Gradient, DeMethod::Potential,
                                                   DeMethod::SinhPotential});
    return frontend::make_node(l.builder(), ir::Kind::Mandelbulb, {power, double(iterations), bailout, method}, {}, at);
  }
  de_method(r, m, "mandelbulb with julia", {DeMethod::Analytic});
  if (power.lo < 2) {
    r.sink().error(m.get("power") ? m.get("power")->loc : at,
                   fmt::format("mandelbulb.power: a Juliabulb needs power >= 2, got {}", power.lo), "");
    return ir::kNoNode;
  }
  // The Juliabulb's far field needs the root of R^power - R - |c|, found at
  // compile time, so its power stays static.
  if (power.animated()) {
    r.sink().error(m.get("power")->loc, "mandelbulb.power cannot be animated in a Juliabulb (with julia)",
                   "animate the power of a plain mandelbulb");
    return ir::kNoNode;
  }
  frontend::Vec3d c = m.vec3("julia", {0, 0, 0}, Range::closed(-4, 4));
  return frontend::make_node(l.builder(), ir::Kind::Juliabulb, {power, double(iterations), bailout, c[0], c[1], c[2]},
                             {}, at);
}

namespace described {
extern const Description Mandelbulb{
    .kind = ir::Kind::Mandelbulb, .yaml = "mandelbulb", .example = "{mandelbulb: {power: 8, iterations: 10}}",
    .param_count = count_of<MandelbulbP>(), .lower = lower_mandelbulb, .props = props, .call_args = {},
    .distance = distance, .dual_normals = true, .emit = emit, .emit_orbit = emit_orbit, .emit_dual = emit_dual,
    .orbit_colour = orbit_colour, .de_summary = de_summary,
    .escape_time = true, .ball_bounds = true, .summary = "an estimate (a bound in practice, not proven)", .docs = k_docs};
}

}  // namespace sdfc::kinds
