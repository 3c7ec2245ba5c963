// The Juliabulb (a mandelbulb with julia: c): z -> z^power + c, c fixed.
// Written `mandelbulb` in scenes; mandelbulb.cpp lowers both.
#include <fmt/format.h>

#include "fractal.hpp"

SDFC_KIND(Juliabulb, 18, "mandelbulb_julia", Fractal, 0, "power,iterations,bailout,cx,cy,cz", "de_juliabulb")

namespace sdfc::kinds {
namespace {
using ir::DeMethod;

struct JuliabulbP {
  double power, iterations, bailout;
  V3 c;
};
constexpr size_t kPower = SDFC_AT(JuliabulbP, power), kBailout = SDFC_AT(JuliabulbP, bailout);

ir::Props props(const ir::Node& n) {
  auto b = view<JuliabulbP>(n);
  return estimate(ir::julia_set_radius(b.power, orbit::len(b.c)), 10 + b.iterations * 45);
}

std::string emit(Emitter& e) {
  auto b = view<JuliabulbP>(e.n);
  std::string radius = e.real(ir::julia_set_radius(b.power, orbit::len(b.c)));
  std::string c = e.vec3(b.c);
  if (integer_power(b.power))
    return fmt::format("{}({}, {}, {}, {}, {}, 1, {})", e.call("de_mandelbulb_int"), e.p, int(b.power),
                       int(b.iterations), bulb_estimator_radius(e, kPower, kBailout), radius, c);
  return fmt::format("{}({}, {}, {}, {}, {}, {})", e.call("de_juliabulb"), e.p, e.param(kPower), int(b.iterations),
                     bulb_estimator_radius(e, kPower, kBailout), radius, c);
}

std::string emit_orbit(Emitter& e) {
  auto b = view<JuliabulbP>(e.n);
  std::string c = e.vec3(b.c);
  // Trig-free like the distance, but the iterations AOV keeps the trig orbit.
  if (integer_power(b.power) && !e.n.animation(kPower) && e.value != codegen::detail::OrbitValue::Escape)
    return orbit_call(e, "trap_mandelbulb_int",
                      fmt::format("{}, {}, {}, {}, {}, {}", e.p, int(b.power), int(b.iterations), e.param(kBailout), 1, c),
                      true);
  return orbit_call(
      e, "trap_mandelbulb",
      fmt::format("{}, {}, {}, {}, {}, {}", e.p, e.param(kPower), int(b.iterations), e.param(kBailout), 1, c), true);
}

std::string emit_dual(Emitter& e) {
  auto b = view<JuliabulbP>(e.n);
  return fmt::format("{}({}, {}, {}, {}, 1, {})", e.call("deg_mandelbulb"), e.p, e.real(b.power), int(b.iterations),
                     bulb_estimator_radius(e, kPower, kBailout), e.vec3(b.c));
}

double distance(const ir::Node& n, const V3& p) {
  using orbit::len;
  auto b = view<JuliabulbP>(n);
  double power = b.power, bailout = ir::bulb_estimator_radius(b.power, b.bailout);
  int iterations = int(b.iterations);
  V3 c = b.c, z = p;
  double dr = 1, r = len(z);
  for (int i = 0; i < iterations && r < bailout; ++i) {
    double rp;
    V3 zn = orbit::bulb_power(z, power, &rp);
    dr = power * rp * dr;
    for (int k = 0; k < 3; ++k) z[k] = zn[k] + c[k];
    r = len(z);
  }
  double radius = ir::julia_set_radius(power, len(c));
  double r0 = len(p);
  if (r0 > 1.5 * radius) return r0 - radius;
  return 0.5 * std::log(std::max(r, 1e-20)) * r / dr;
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  auto b = view<JuliabulbP>(n);
  int iterations = int(b.iterations), k = 0;
  double trap = 1e10;
  V3 z = p;
  for (; k < iterations && orbit::len(z) < b.bailout; ++k) {
    V3 w = orbit::bulb(z, b.power);
    for (int i = 0; i < 3; ++i) z[i] = w[i] + b.c[i];
    trap = std::min(trap, orbit::measure(shape, z));
  }
  return {trap, orbit::smooth_iteration(k, orbit::len(z), b.bailout, b.power, true, iterations)};
}

std::string de_summary(const ir::Node&) { return de_words(DeMethod::Analytic); }

static constexpr ParamDoc k_docs[] = {
    {"power", "number", "8", "2 to 64, not animated", "the exponent of z -> z^power + julia"},
    {"iterations", "integer", "10", "1 to 1000", "orbit steps: more gives finer detail"},
    {"bailout", "number", "2", "> 0, up to 1000", "the radius past which an orbit has escaped"},
    {"julia", "vec3", "", "each -4 to 4", "the fixed c added at every step (without it the node is a Mandelbulb)"},
};

}  // namespace

namespace described {
extern const Description Juliabulb{
    .kind = ir::Kind::Juliabulb, .yaml = "mandelbulb", .example = "{mandelbulb: {power: 8, julia: [0.3, -0.4, 0.2]}}",
    .param_count = count_of<JuliabulbP>(), .lower = lower_mandelbulb, .props = props, .call_args = {},
    .distance = distance, .dual_normals = true, .emit = emit, .emit_orbit = emit_orbit, .emit_dual = emit_dual,
    .orbit_colour = orbit_colour, .de_summary = de_summary,
    .escape_time = true, .ball_bounds = true, .summary = "an estimate (a bound in practice, not proven); mandelbulb with julia", .docs = k_docs};
}

}  // namespace sdfc::kinds
