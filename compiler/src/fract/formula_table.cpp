// The formula table (see formula_table.hpp): the mapped formulas' writers,
// then every id Mandelbulber 2.20 knows with its name.
#include "formula_writers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sdfc::fract {
namespace {

struct NameRow {
  int id;
  const char* name;
};
constexpr NameRow kNames[] = {
#include "formula_names.inc"
};

}  // namespace

std::string from(const FormulaInput& in, const std::string& key) {
  return fmt::format("[fractal_{}] {}", in.slot, key);
}

// Mandelbulber's N counts iterations for every formula; sdfc caps each
// kind where more iterations change nothing visible. The field's comment says so.
Field iterations_field(const FormulaInput& in, int cap) {
  if (in.iterations <= cap) return {"iterations", std::to_string(std::max(in.iterations, 1)), "N"};
  return {"iterations", std::to_string(cap), fmt::format("N = {}, sdfc's cap (no visible difference)", in.iterations)};
}

void require_c_added(const FormulaInput& in) {
  if (in.main.boolean(fmt::format("dont_add_c_constant_{}", in.slot)))
    unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true");
  Vec3 k = in.main.vec3("fractal_constant_factor");
  if (k != Vec3{1, 1, 1}) unsupported_setting(in, "fractal_constant_factor", vec(k));
}

namespace {

// Tglad's Mandelbox (mandelbox.cl): the box fold `sign(z)·folding_value − z`
// beyond folding_limit is sdfc's clamp fold when folding_value = 2 × limit;
// the sphere fold compares |z|² with the squared radii, as sdfc does.
Node mandelbox(const FormulaInput& in) {
  const Params& f = in.fractal;
  ChainPart chain = mandelbox_chain(in);  // refuses what neither form maps
  double scale = f.number("mandelbox_scale");
  // A main rotation, a constant factor, no c or a scale in -1 ... 1: the
  // chain, which has room for them; else the mandelbox kind.
  if (f.boolean("mandelbox_main_rotation_enabled") || in.main.vec3("fractal_constant_factor") != Vec3{1, 1, 1} ||
      !adds_c(in, true) || std::fabs(scale) <= 1)
    return chain_formula(in, chain);
  Node n{"mandelbox", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {{"scale", num(scale), from(in, "mandelbox_scale")},
              {"min_radius", num(f.number("mandelbox_folding_min_radius")), from(in, "mandelbox_folding_min_radius")},
              {"fixed_radius", num(f.number("mandelbox_folding_fixed_radius")), from(in, "mandelbox_folding_fixed_radius")},
              {"folding_limit", num(f.number("mandelbox_folding_limit")), from(in, "mandelbox_folding_limit")},
              iterations_field(in, 200)};
  if (in.julia) n.fields.push_back({"julia", vec(julia_constant(in)), "julia_mode true, julia_c"});
  return n;
}

// The Menger sponge (menger_sponge.cl): sort |z| descending, z·3 − (2, 2, 0),
// z.z −= 2 where z.z > 1 — sdfc's fold with scale 3 and shift scale − 1.
Node menger_sponge(const FormulaInput& in) {
  double s = in.fractal.number("transf_scale_3");
  if (s != 3 || adds_c(in, false)) return chain_formula(in, menger_chain(in));  // the kind has neither
  Node n{"menger", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {{"scale", "3", from(in, "transf_scale_3")},
              iterations_field(in, 12)};
  return n;
}

// The quaternion formula (quaternion.cl) keeps w = 0, so in julia mode it is
// the quaternion Julia set of c = (julia_c, 0) on the slice w = 0, with the
// same log estimator; its Mandelbrot form (c = the point) is the quaternion preset.
Node quaternion(const FormulaInput& in) {
  if (!in.julia) return quaternion_mandelbrot(in);
  require_c_added(in);
  for (double c : in.julia_c)
    if (std::fabs(c) > 4) unsupported_setting(in, "julia_c", vec(in.julia_c));
  if (!(in.bailout > 1 && in.bailout <= 1000)) unsupported_setting(in, "bailout", num(in.bailout));
  Node n{"julia", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {{"c", vec(std::vector<double>{in.julia_c[0], in.julia_c[1], in.julia_c[2], 0}), "julia_c (w = 0)"},
              {"degree", "2", ""},
              iterations_field(in, 1000),
              {"bailout", num(in.bailout), "bailout"}};
  return n;
}

constexpr Formula kMapped[] = {
    {2, "Mandelbulb", 10, mandelbulb, mandelbulb_chain, true},  // its writer mirrors the alpha offset
    {3, "Mandelbulb - Power 2", 10, mandelbulb_power2, mandelbulb_power2_chain, true},
    {4, "Hypercomplex", 10, hypercomplex, nullptr, true},
    {5, "Quaternion", 10, quaternion, nullptr, true},  // y -> -y commutes with squaring: J(c) mirrored is J(mirrored c)
    {7, "Menger sponge", 10, menger_sponge, menger_chain, true},
    {8, "Mandelbox", 100, mandelbox, mandelbox_chain, true},
    {10, "Kaleidoscopic IFS", 10, ifs, ifs_chain, true},  // its writer mirrors its vectors and rotations
    {11, "Xenodreambuie", 10, xenodreambuie, nullptr, true},
    {19, "Aexion", 10, aexion, nullptr, true},
    {16, "box_fold_bulb_pow2", 10000, box_fold_bulb_pow2, box_fold_bulb_pow2_chain, true},
    {61, "Menger - Mod 1", 10, menger_mod1, nullptr, true},
    {70, "eiffie_msltoe", 10, eiffie_msltoe, nullptr, false},
    {98, "Menger - Cross KIFS", 10, menger_cross_kifs, nullptr, true},  // |y| and |z| first
    {103, "pseudoKleinian2", 100, pseudo_kleinian, nullptr, true},      // its writer mirrors the offset
    {113, "Menger - Smooth", 10, menger_smooth, nullptr, true},         // smooth |x|, |y|, |z| first
    {119, "Abox - Mod 11", 100, abox_mod11, abox_mod11_chain, false},
    {132, "Amazing Surf - Mod 2", 100, amazing_surf_mod2, amazing_surf_mod2_chain, false},
};

}  // namespace

const Formula* find_formula(int id) {
  for (const Formula& f : kMapped)
    if (f.id == id) return &f;
  // Known but not mapped: a row without a writer, kept per id.
  static std::vector<Formula> unmapped = [] {
    std::vector<Formula> v;
    for (const NameRow& r : kNames) v.push_back({r.id, r.name, 10, nullptr, nullptr, false});
    return v;
  }();
  for (const Formula& f : unmapped)
    if (f.id == id) return &f;
  return nullptr;
}

std::string formula_name(int id) {
  const Formula* f = find_formula(id);
  return f ? f->name : fmt::format("formula id {}", id);
}

std::string formula_label(int id) {
  const Formula* f = find_formula(id);
  return f ? fmt::format("formula '{}' (id {})", f->name, id) : fmt::format("formula id {}", id);
}

void unsupported_setting(const FormulaInput& in, const std::string& key, const std::string& what) {
  SourceLoc at = in.main.given(key) ? in.main.loc(key) : in.fractal.given(key) ? in.fractal.loc(key) : in.loc;
  fail(at, fmt::format("formula '{}' (id {}) with {} = {} is not supported yet", in.name, in.id, key,
                       printable(what, 100)),
       "sdfc maps this formula only where its shape is the same");
}

}  // namespace sdfc::fract
