// menger and sierpinski: fold, scale about a corner, repeat (the Menger
// sponge's sort-and-shift, Sierpinski's tetrahedral folds).
#include <fmt/format.h>

#include "../frontend/animated_node.hpp"
#include "fractal.hpp"

SDFC_KIND(Menger, 21, "menger", Fractal, 0, "iterations,scale", "de_menger")
SDFC_KIND(Sierpinski, 22, "sierpinski", Fractal, 0, "iterations,scale", "de_sierpinski")

namespace sdfc::kinds {
namespace {
using frontend::Param;
using frontend::Range;

struct FoldP {
  double iterations, scale;
};
constexpr size_t kScale = SDFC_AT(FoldP, scale);

ir::NodeId lower_menger(Lowering& l) {
  frontend::MapReader m(l.reader(), l.body(), "menger", {"iterations", "scale", "de"});
  de_method(l.reader(), m, "menger", {ir::DeMethod::Analytic});
  int iterations = m.integer("iterations", 4, 1, 12);
  Param scale = m.param("scale", 3.0, Range::closed(2, 4));
  return l.make_animated({double(iterations), scale});
}

ir::NodeId lower_sierpinski(Lowering& l) {
  frontend::MapReader m(l.reader(), l.body(), "sierpinski", {"iterations", "scale", "de"});
  de_method(l.reader(), m, "sierpinski", {ir::DeMethod::Analytic});
  int iterations = m.integer("iterations", 8, 1, 30);
  Param scale = m.param("scale", 2.0, {1, 4, true});
  return l.make_animated({double(iterations), scale});
}

ir::Props props_menger(const ir::Node& n) { return estimate(1.0, 20 + view<FoldP>(n).iterations * 20); }
ir::Props props_sierpinski(const ir::Node& n) { return estimate(1.0, 20 + view<FoldP>(n).iterations * 16); }

std::string args(const Emitter& e) { return fmt::format("{}, {}", int(view<FoldP>(e.n).iterations), e.param(kScale)); }

std::string emit_menger(Emitter& e) { return fmt::format("{}({}, {})", e.call("de_menger"), e.p, args(e)); }
std::string emit_sierpinski(Emitter& e) { return fmt::format("{}({}, {})", e.call("de_sierpinski"), e.p, args(e)); }

// Folding fractals never escape: their escape step is the configured count.
std::string orbit(Emitter& e, const char* fn) {
  if (e.value == codegen::detail::OrbitValue::Escape) return e.lit.typed(view<FoldP>(e.n).iterations);
  return orbit_call(e, fn, fmt::format("{}, {}", e.p, args(e)), false);
}
std::string orbit_menger(Emitter& e) { return orbit(e, "trap_menger"); }
std::string orbit_sierpinski(Emitter& e) { return orbit(e, "trap_sierpinski"); }

// The Menger step: |z| sorted descending, scaled about (1, 1, 1), the
// middle slab shifted back.
void fold_menger(V3& z, double scale) {
  double shift = scale - 1;
  orbit::sort_descending(z);
  for (double& c : z) c = scale * c - shift;
  if (z[2] < -0.5 * shift) z[2] += shift;
}

// Sierpinski's step: the tetrahedral folds, scaled about (1, 1, 1).
void sierpinski_step(V3& z, double scale) {
  orbit::tetra_folds(z);
  for (double& c : z) c = scale * c - (scale - 1);
}

// The orbit's trap (nothing escapes: the iteration count is always 1).
reference::OrbitColour colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape, void (*step)(V3&, double)) {
  auto f = view<FoldP>(n);
  double trap = 1e10;
  V3 z = p;
  for (int i = 0; i < int(f.iterations); ++i) {
    step(z, f.scale);
    trap = std::min(trap, orbit::measure(shape, z));
  }
  return {trap, 1.0};
}
reference::OrbitColour colour_menger(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  return colour(n, p, shape, fold_menger);
}
reference::OrbitColour colour_sierpinski(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  return colour(n, p, shape, sierpinski_step);
}

// z after the iterations; *s the scales' product.
V3 folded(const ir::Node& n, const V3& p, void (*step)(V3&, double), double* s) {
  auto f = view<FoldP>(n);
  *s = 1;
  V3 z = p;
  for (int i = 0; i < int(f.iterations); ++i) {
    step(z, f.scale);
    *s *= f.scale;
  }
  return z;
}

double distance_menger(const ir::Node& n, const V3& p) {
  double s;
  V3 z = folded(n, p, fold_menger, &s);
  // Distance to the cube [-1, 1]^3.
  V3 d{std::fabs(z[0]) - 1, std::fabs(z[1]) - 1, std::fabs(z[2]) - 1};
  V3 out{std::max(d[0], 0.0), std::max(d[1], 0.0), std::max(d[2], 0.0)};
  return (orbit::len(out) + std::min(std::max({d[0], d[1], d[2]}), 0.0)) / s;
}

double distance_sierpinski(const ir::Node& n, const V3& p) {
  double s;
  V3 z = folded(n, p, sierpinski_step, &s);
  // The tetrahedron with vertices (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1):
  // the largest of its four face-plane distances.
  double faces = std::max({-z[0] - z[1] - z[2], z[0] + z[1] - z[2], -z[0] + z[1] + z[2], z[0] - z[1] + z[2]});
  return (faces - 1) / std::sqrt(3.0) / s;
}

std::string de_summary(const ir::Node&) { return de_words(ir::DeMethod::Analytic); }

static constexpr ParamDoc k_menger_docs[] = {
    {"iterations", "integer", "4", "1 to 12", "levels of holes"},
    {"scale", "number", "3", "2 to 4", "the shrink per level: 3 is the classic sponge"},
    {"de", "one of analytic", "analytic", "", "the distance estimator"},
};
static constexpr ParamDoc k_sierpinski_docs[] = {
    {"iterations", "integer", "8", "1 to 30", "levels of the tetrahedron"},
    {"scale", "number", "2", "> 1, up to 4", "the shrink per level: 2 is the classic gasket"},
    {"de", "one of analytic", "analytic", "", "the distance estimator"},
};

}  // namespace

namespace described {
extern const Description Menger{
    .kind = ir::Kind::Menger, .yaml = "menger", .example = "{menger: {iterations: 4}}",
    .param_count = count_of<FoldP>(), .lower = lower_menger, .props = props_menger, .call_args = {},
    .distance = distance_menger, .emit = emit_menger, .emit_orbit = orbit_menger, .orbit_colour = colour_menger,
    .de_summary = de_summary, .summary = "an estimate (a bound in practice, not proven)", .docs = k_menger_docs};
extern const Description Sierpinski{
    .kind = ir::Kind::Sierpinski, .yaml = "sierpinski", .example = "{sierpinski: {iterations: 8}}",
    .param_count = count_of<FoldP>(), .lower = lower_sierpinski, .props = props_sierpinski, .call_args = {},
    .distance = distance_sierpinski, .emit = emit_sierpinski, .emit_orbit = orbit_sierpinski,
    .orbit_colour = colour_sierpinski, .de_summary = de_summary,
    .summary = "an estimate (a bound in practice, not proven)", .docs = k_sierpinski_docs};
}

}  // namespace sdfc::kinds
