// The formula table (see formula_table.hpp): the mapped formulas' writers,
// then every id Mandelbulber 2.20 knows with its name.
#include "formula_table.hpp"

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

// Tglad's Mandelbox (mandelbox.cl): the box fold `sign(z)·folding_value − z`
// beyond folding_limit is sdfc's clamp fold when folding_value = 2 × limit;
// the sphere fold compares |z|² with the squared radii, as sdfc does.
Node mandelbox(const FormulaInput& in) {
  const Params& f = in.fractal;
  double scale = f.number("mandelbox_scale"), limit = f.number("mandelbox_folding_limit");
  double value = f.number("mandelbox_folding_value");
  double min_r = f.number("mandelbox_folding_min_radius"), fixed_r = f.number("mandelbox_folding_fixed_radius");
  if (f.boolean("mandelbox_rotations_enabled")) unsupported_setting(in, "mandelbox_rotations_enabled", "true");
  if (f.boolean("mandelbox_main_rotation_enabled")) unsupported_setting(in, "mandelbox_main_rotation_enabled", "true");
  if (f.vec3("mandelbox_offset") != Vec3{0, 0, 0}) unsupported_setting(in, "mandelbox_offset", vec(f.vec3("mandelbox_offset")));
  if (std::fabs(value - 2 * limit) > 1e-12 * std::max(1.0, std::fabs(limit)))
    unsupported_setting(in, "mandelbox_folding_value", num(value) + " (only 2 x mandelbox_folding_limit maps)");
  if (!(std::fabs(scale) > 1 && std::fabs(scale) <= 8)) unsupported_setting(in, "mandelbox_scale", num(scale));
  if (!(min_r > 0 && min_r < fixed_r && fixed_r <= 100))
    unsupported_setting(in, "mandelbox_folding_min_radius", num(min_r) + " with fixed radius " + num(fixed_r));
  if (!(limit > 0)) unsupported_setting(in, "mandelbox_folding_limit", num(limit));
  require_c_added(in);
  Node n{"mandelbox", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {{"scale", num(scale), from(in, "mandelbox_scale")},
              {"min_radius", num(min_r), from(in, "mandelbox_folding_min_radius")},
              {"fixed_radius", num(fixed_r), from(in, "mandelbox_folding_fixed_radius")},
              {"folding_limit", num(limit), from(in, "mandelbox_folding_limit")},
              iterations_field(in, 200)};
  if (in.julia) {
    for (double c : in.julia_c)
      if (std::fabs(c) > 10) unsupported_setting(in, "julia_c", vec(in.julia_c));
    n.fields.push_back({"julia", vec(in.julia_c), "julia_mode true, julia_c"});
  }
  return n;
}

// The Menger sponge (menger_sponge.cl): sort |z| descending, z·3 − (2, 2, 0),
// z.z −= 2 where z.z > 1 — sdfc's fold with scale 3 and shift scale − 1.
Node menger_sponge(const FormulaInput& in) {
  double s = in.fractal.number("transf_scale_3");
  if (s != 3) unsupported_setting(in, "transf_scale_3", num(s) + " (only 3 maps: Mandelbulber shifts by 2 at any scale)");
  if (in.main.boolean(fmt::format("dont_add_c_constant_{}", in.slot)))  // this formula adds no c unless asked
    unsupported_setting(in, fmt::format("dont_add_c_constant_{}", in.slot), "true (adds c)");
  Node n{"menger", fmt::format("formula_{} {} ({})", in.slot, in.id, in.name), {}, {}, {}};
  n.fields = {{"scale", "3", from(in, "transf_scale_3")},
              iterations_field(in, 12)};
  return n;
}

// The quaternion formula (quaternion.cl) keeps w = 0, so in julia mode it is
// the quaternion Julia set of c = (julia_c, 0) on the slice w = 0, with the
// same log estimator; its Mandelbrot form (c = the point) has no sdfc kind.
Node quaternion(const FormulaInput& in) {
  if (!in.julia) unsupported_setting(in, "julia_mode", "false (the Mandelbrot form; julia mode maps)");
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
    {5, "Quaternion", 10, quaternion, true},  // y -> -y commutes with squaring: J(c) mirrored is J(mirrored c)
    {7, "Menger sponge", 10, menger_sponge, true},
    {8, "Mandelbox", 100, mandelbox, true},
};

}  // namespace

const Formula* find_formula(int id) {
  for (const Formula& f : kMapped)
    if (f.id == id) return &f;
  // Known but not mapped: a row without a writer, kept per id.
  static std::vector<Formula> unmapped = [] {
    std::vector<Formula> v;
    for (const NameRow& r : kNames) v.push_back({r.id, r.name, 10, nullptr, false});
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
