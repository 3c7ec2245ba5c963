// kifs: Knighty's kaleidoscopic IFS: rotate, fold by a symmetry group,
// scale about an offset, rotate again.
#include <fmt/format.h>

#include <numbers>

#include "fractal.hpp"

SDFC_KIND(Kifs, 23, "kifs", Fractal, 0, "symmetry,scale,ox,oy,oz,iterations,b00,b01,b02,b10,b11,b12,b20,b21,b22,a00,a01,a02,a10,a11,a12,a20,a21,a22", "de_kifs")

namespace sdfc::kinds {
namespace {
using frontend::Range;
using ir::KifsSymmetry;
using M3 = std::array<double, 9>;  // row-major

struct KifsP {
  double symmetry, scale;  // symmetry: an ir::KifsSymmetry code
  V3 offset;               // the scaling centre
  double iterations;
  M3 before, after;        // the rotations before the fold and after the scaling
};
constexpr size_t kScale = SDFC_AT(KifsP, scale);

M3 rotation(frontend::ValueReader& r, const frontend::MapReader& m, std::string_view key) {
  const SourceValue* v = m.get(key);
  if (!v) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  frontend::MapReader rm(r, *v, fmt::format("kifs.{}", key), {"axis", "degrees"});
  frontend::Vec3d axis = rm.require("axis") ? rm.direction("axis", {0, 0, 1}) : frontend::Vec3d{0, 0, 1};
  double deg = rm.require("degrees") ? rm.number("degrees", 0, Range::closed(-36000, 36000)) : 0;
  return ir::axis_rotation(axis, deg);
}

ir::NodeId lower(Lowering& l) {
  frontend::ValueReader& r = l.reader();
  frontend::MapReader m(r, l.body(), "kifs", {"symmetry", "scale", "offset", "rotate_before", "rotate_after", "iterations", "de"});
  de_method(r, m, "kifs", {ir::DeMethod::Analytic});
  std::string sym = m.word("symmetry", "tetrahedral", {"tetrahedral", "octahedral", "icosahedral", "menger"});
  double code = sym == "tetrahedral" ? 0 : sym == "octahedral" ? 1 : sym == "icosahedral" ? 2 : 3;
  double scale = m.number("scale", 2.0, {1, 4, true});
  frontend::Vec3d offset = m.vec3("offset", {1, 1, 1}, Range::closed(-10, 10));
  if (orbit::len(offset) < 1e-6) {
    r.sink().error(m.get("offset")->loc, "kifs.offset: must not be zero (it is the scaling centre)", "");
    offset = {1, 1, 1};
  }
  int iterations = m.integer("iterations", 12, 1, 40);
  M3 before = rotation(r, m, "rotate_before"), after = rotation(r, m, "rotate_after");
  return l.make(KifsP{code, scale, offset, double(iterations), before, after});
}

ir::Props props(const ir::Node& n) {
  // Every map of the IFS moves points beyond |offset| further out, so the
  // attractor lies in the ball of radius |offset|; the estimator's cover
  // by balls adds |offset| / scale^n.
  auto k = view<KifsP>(n);
  double o = orbit::len(k.offset);
  return estimate(o * (1 + std::pow(k.scale, -k.iterations)) * 1.02 + 1e-3, 10 + k.iterations * (k.symmetry == 2 ? 70 : 40));
}

std::string rows(const Emitter& e, const M3& m) {
  return fmt::format("{}, {}, {}", e.vec3({m[0], m[1], m[2]}), e.vec3({m[3], m[4], m[5]}), e.vec3({m[6], m[7], m[8]}));
}

// The arguments after p that the estimator and the trap function share.
std::string args(const Emitter& e) {
  auto k = view<KifsP>(e.n);
  return fmt::format("{}, {}, {}, {}, {}, {}", int(k.symmetry), e.param(kScale), e.vec3(k.offset), int(k.iterations),
                     rows(e, k.before), rows(e, k.after));
}

std::string emit(Emitter& e) { return fmt::format("{}({}, {})", e.call("de_kifs"), e.p, args(e)); }

std::string emit_orbit(Emitter& e) {
  // A folding fractal never escapes: its escape step is the configured count.
  if (e.value == codegen::detail::OrbitValue::Escape) return e.lit.typed(view<KifsP>(e.n).iterations);
  return orbit_call(e, "trap_kifs", fmt::format("{}, {}", e.p, args(e)), false);
}

// Reflect z in the plane with unit normal n (through the origin) if dot > 0.
void reflect_if_positive(V3& z, const V3& n) {
  double t = orbit::dot(z, n);
  if (t > 0)
    for (int i = 0; i < 3; ++i) z[i] -= 2 * t * n[i];
}

// The orbit from p, calling visit(z) after each step; returns the scale's product.
template <class Visit>
double run(const KifsP& k, const V3& p, V3& z, Visit visit) {
  auto symmetry = KifsSymmetry(int(k.symmetry));
  double scale = k.scale, s = 1;
  const double g = std::numbers::phi;
  V3 n1{-g, g - 1, 1}, n2{1, -g, g + 1};
  for (V3* n : {&n1, &n2}) {
    double l = orbit::len(*n);
    for (double& c : *n) c /= l;
  }
  z = p;
  for (int i = 0; i < int(k.iterations); ++i) {
    z = orbit::apply(k.before, z);
    switch (symmetry) {
      case KifsSymmetry::Tetrahedral: orbit::tetra_folds(z); break;
      case KifsSymmetry::Icosahedral:
        for (int f = 0; f < 3; ++f) {
          for (double& c : z) c = std::fabs(c);
          reflect_if_positive(z, n1);
          reflect_if_positive(z, n2);
        }
        break;
      case KifsSymmetry::Octahedral:
      case KifsSymmetry::Menger: orbit::sort_descending(z); break;
    }
    for (int a = 0; a < 3; ++a) z[a] = scale * z[a] - k.offset[a] * (scale - 1);
    if (symmetry == KifsSymmetry::Menger && z[2] < -0.5 * k.offset[2] * (scale - 1)) z[2] += k.offset[2] * (scale - 1);
    z = orbit::apply(k.after, z);
    s *= scale;
    visit(z);
  }
  return s;
}

double distance(const ir::Node& n, const V3& p) {
  auto k = view<KifsP>(n);
  V3 z;
  double s = run(k, p, z, [](const V3&) {});
  // The level-n cover of the attractor (inside |offset|) by balls.
  return (orbit::len(z) - orbit::len(k.offset)) / s;
}

reference::OrbitColour orbit_colour(const ir::Node& n, const V3& p, const ir::TrapShape& shape) {
  double trap = 1e10;
  V3 z;
  run(view<KifsP>(n), p, z, [&](const V3& at) { trap = std::min(trap, orbit::measure(shape, at)); });
  return {trap, 1.0};
}

std::string de_summary(const ir::Node&) { return de_words(ir::DeMethod::Analytic); }

static constexpr ParamDoc k_docs[] = {
    {"symmetry", "one of tetrahedral|octahedral|icosahedral|menger", "tetrahedral", "", "the fold's symmetry group"},
    {"scale", "number", "2", "> 1, up to 4", "the expansion per step about the offset"},
    {"offset", "vec3", "[1, 1, 1]", "each -10 to 10, not zero", "the scaling centre: the attractor lies within |offset|"},
    {"rotate_before", "map (axis, degrees)", "", "", "a rotation before each fold"},
    {"rotate_after", "map (axis, degrees)", "", "", "a rotation after each scaling"},
    {"iterations", "integer", "12", "1 to 40", "orbit steps: more gives finer detail"},
    {"de", "one of analytic", "analytic", "", "the distance estimator"},
};

}  // namespace

namespace described {
extern const Description Kifs{
    .kind = ir::Kind::Kifs, .yaml = "kifs", .example = "{kifs: {symmetry: octahedral, scale: 2}}",
    .param_count = count_of<KifsP>(), .lower = lower, .props = props, .call_args = {}, .distance = distance,
    .emit = emit, .emit_orbit = emit_orbit, .orbit_colour = orbit_colour, .de_summary = de_summary,
    .bounds_trust = 0.5, .summary = "an estimate (a bound in practice, not proven)", .docs = k_docs};
}

}  // namespace sdfc::kinds
