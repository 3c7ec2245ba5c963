// The fractal estimators on every OpenCL evaluator against the
// CPU reference. To keep kernel builds few, each group scene places several
// fractals side by side in one union; the points are sampled around each
// member (uniform in its box, dense along rays through its surface, and far
// away), at least 1000 per fractal.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>

#include "conformance.hpp"

namespace sdfc::conformance {
namespace {

using test::add;
using test::mul;

struct Member {
  std::string name;
  std::string node;  // the YAML geometry node, without translate
  double radius;     // half the side of a box around it
};

struct Group {
  std::string name;
  std::vector<Member> members;
  double spacing;
  double float_rel = 2e-3;  // relative part of the float tolerance (see fractal_tolerance)
  // Inside, where a superattracting orbit's Jacobian (Newton's method near
  // a root) is a cancellation, only the sign is reproducible.
  bool inside_sign = false;
};

void PrintTo(const Group& g, std::ostream* os) { *os << g.name; }

std::vector<Group> groups() {
  return {
      {"folds",
       {{"mandelbox", "mandelbox: {scale: -1.5, iterations: 12}", 2.2},
        {"mandelbox_julia", "mandelbox: {scale: 2, julia: [0.8, -0.4, 0.3], iterations: 10}, scale: 0.25", 2.2},
        {"mandelbox_nonconformal", "mandelbox: {scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], iterations: 12}", 2.2},
        {"menger", "menger: {iterations: 4}", 1.2},
        {"sierpinski", "sierpinski: {iterations: 8}", 1.2}},
       6.0},
      {"julias",
       {{"julia2", "julia: {c: [-0.2, 0.6, 0.2, 0.2], degree: 2, iterations: 12}", 1.6},
        {"julia3_slice", "julia: {c: [-0.6, 0.3, 0.2, 0.1], degree: 3, iterations: 10, slice: 0.15}", 1.6},
        {"juliabulb8", "mandelbulb: {power: 8, julia: [0.35, -0.3, 0.2], iterations: 8}", 1.4},
        {"juliabulb_real_power", "mandelbulb: {power: 6.5, julia: [0.3, 0.2, -0.4], iterations: 8}", 1.4},
        {"mandelbulb_trig_power", "mandelbulb: {power: 7.5, iterations: 8}", 1.3},
        {"hybrid", "hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2}}], repeat: [1, 2], iterations: 9, bailout: 3}", 1.8}},
       5.0},
      {"kifs",
       {{"kifs_tetra", "kifs: {symmetry: tetrahedral, scale: 2, iterations: 10, rotate_before: {axis: [1, 0, 0], degrees: 12}}", 1.9},
        {"kifs_octa", "kifs: {symmetry: octahedral, scale: 2, offset: [1, 0.6, 0.3], iterations: 10}", 1.3},
        {"kifs_icosa", "kifs: {symmetry: icosahedral, scale: 2.3, offset: [0.85, 0.53, 0], iterations: 9, rotate_after: {axis: [0, 0, 1], degrees: 15}}", 1.1},
        {"kifs_menger", "kifs: {symmetry: menger, scale: 3, iterations: 4}", 1.8}},
       5.0},
      {"methods",
       {{"mandelbox_jacobian", "mandelbox: {scale: -1.5, iterations: 12, de: jacobian}", 2.2},
        {"mandelbox_nonconformal_dual", "mandelbox: {scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], iterations: 12, de: dual}", 2.2},
        {"mandelbox_julia_jacobian", "mandelbox: {scale: 2, julia: [0.8, -0.4, 0.3], iterations: 10, de: jacobian}, scale: 0.25", 2.2},
        {"menger_step_factor", "menger: {iterations: 3}, step_factor: 0.7", 1.2}},
       6.0},
      {"bulb_methods",
       {{"bulb_gradient", "mandelbulb: {power: 8, iterations: 8, de: gradient}", 1.3},
        {"bulb_potential", "mandelbulb: {power: 8, iterations: 8, de: potential}", 1.3},
        {"bulb_sinh", "mandelbulb: {power: 8, iterations: 8, de: sinh}", 1.3},
        {"bulb_gradient_trig", "mandelbulb: {power: 7.5, iterations: 8, de: gradient}", 1.3}},
       4.0,
       // Four-point forward differences with eps = 1e-4 in float: the taps
       // differ from the centre by |grad| 1e-4 while each carries ~1 ulp
       // (~2.4e-7) of rounding, so the gradient has ~1e-3 relative error.
       5e-3},
      // Formula chains (compiler/src/formula/): the scalar derivative, the
      // Jacobian (forced by a non-conformal step, an expr or de: jacobian),
      // julia, windows and repeat_from.
      {"formula_folds",
       {{"chain_mandelbox", "formula: {iterations: 12, iterate: [box_fold, sphere_fold, {scale: -1.5}, add_c]}", 2.2},
        {"chain_nonconformal",
         "formula: {iterations: 12, iterate: [box_fold, sphere_fold, {scale: -1.5}, {scale_xyz: [1.2, 1.0, 0.8]}, add_c]}", 2.2},
        {"chain_folds_rotated",
         "formula: {iterations: 10, julia: [0.6, -0.3, 0.2], iterate: [{abs: {axes: [1, 0, 1]}}, {plane_fold: {normal: [1, 1, 0], offset: 0.2}},"
         " {box_fold: {limit: 1.2}}, {rotate: {axis: [1, 0, 0], angle: 15}}, sphere_fold, {scale: {scale: 2, offset: [0.1, 0, 0]}}, add_c]}",
         2.2}},
       6.0},
      {"formula_power",
       {{"chain_bulb8", "formula: {iterations: 8, bailout: 8, iterate: [{bulb_power: 8}, add_c]}", 1.3},
        {"chain_bulb8_jacobian", "formula: {iterations: 8, bailout: 8, de: jacobian, iterate: [{bulb_power: 8}, add_c]}", 1.3},
        {"chain_bulb2_expr",
         "formula: {iterations: 10, bailout: 8, iterate: [{expr: {x: \"2*z*(x*x - y*y) / sqrt(x*x + y*y + 1e-30)\","
         " y: \"4*x*y*z / sqrt(x*x + y*y + 1e-30)\", z: \"z*z - x*x - y*y\"}}, add_c]}",
         1.6},
        {"chain_hybrid_window",
         "formula: {iterations: 10, bailout: 8, repeat_from: 1, iterate: [{rotate: {axis: [0, 0, 1], angle: 20}}, {bulb_power: 3},"
         " add_c, {box_fold: {limit: 1, from: 2, until: 5}}]}",
         1.6}},
       4.0},
      // Presets and the steps the Mandelbulber presets need: the pseudo-Kleinian
      // (its own estimate), Amazing Surf, and the inversions, polyfold and
      // icosa_fold with the scalar derivative and the Jacobian.
      {"formula_presets",
       {{"preset_pseudo_kleinian", "pseudo_kleinian: {iterations: 8}", 1.6},
        {"preset_amazing_surf", "amazing_surf: {scale: 1.8, rotation_axis: [1, 1, 0], rotation_angle: 30, iterations: 10}", 2.2},
        {"preset_xenodreambuie", "xenodreambuie: {iterations: 8}", 1.6},
        {"preset_eiffie_msltoe", "eiffie_msltoe: {iterations: 8, julia: [0.3, 0.6, 0.1]}", 2.0},
        {"chain_new_folds",
         "formula: {iterations: 10, iterate: [{polyfold: {order: 5, until: 2}}, icosa_fold, {surf_fold: {limit: [0.9, 1, 1.1], axes: [1, 1, 1]}},"
         " {kleinian_fold: {min_r2: 0.4}}, {spherical_invert: {radius: 1.2, centre: [0.1, 0, 0], from: 1, until: 2}}, {scale: -1.8}, add_c]}",
         2.2},
        {"chain_new_folds_jacobian",
         "formula: {iterations: 10, de: jacobian, iterate: [{polyfold: {order: 5, until: 2}}, icosa_fold, {surf_fold: {limit: [0.9, 1, 1.1], axes: [1, 1, 1]}},"
         " {kleinian_fold: {min_r2: 0.4}}, {spherical_invert: {radius: 1.2, centre: [0.1, 0, 0], from: 1, until: 2}}, {scale: -1.8}, add_c]}",
         2.2}},
       6.0},
      // The ABox and Amazing Surf variants; the Menger variants and the Koch IFS.
      {"formula_presets_box",
       {{"preset_abox_mod11", "abox_mod11: {scale: -1.5, iterations: 10}", 2.2},
        {"preset_amazing_surf_mod2", "amazing_surf_mod2: {scale: 1.8, rotation_axis: [1, 1, 0], rotation_angle: 30, iterations: 10}", 2.2},
        {"preset_amazing_surf_mod4", "amazing_surf_mod4: {scale: 1.8, min_r2: 0.3, rotation_axis: [1, 1, 0], rotation_angle: 30, iterations: 10}", 2.2},
        {"preset_abox_mod15", "abox_mod15: {scale: -1.5, offset: [0.1, 0, 0], iterations: 10}", 2.2}},
       6.0},
      {"formula_presets_menger",
       {{"preset_menger_mod1", "menger_mod1: {multiplier: [1, 0.85, 1], offset: [0.15, 0, 0], iterations: 8}", 2.2},
        {"preset_menger_cross_kifs", "menger_cross_kifs: {iterations: 8}", 3.0},
        {"preset_menger3", "menger3: {iterations: 8}", 2.2},
        {"preset_koch", "koch: {iterations: 8}", 2.0},
        {"preset_menger_smooth", "menger_smooth: {iterations: 6}", 2.2}},
       6.0},
      // Jos Leys' Kleinian: wrap, the flip above the sine line, the inversion, its own estimate.
      {"formula_presets_jos_kleinian",
       {{"preset_jos_kleinian", "jos_kleinian: {iterations: 8, bailout: 2.5}", 1.2},
        {"preset_jos_kleinian_shifted",
         "jos_kleinian: {height: 1.9, shift: 0.073, box_size: [0.9, 1.1, 1.2], spheres: 0, de_cap: 0.28, iterations: 8, bailout: 2.5}", 1.2}},
       6.0},
      // The 4-D chains: the quaternion Julia preset (slice, cubic and the
      // Jacobian's w row too), Quaternion, Hypercomplex and Aexion, and a
      // chain whose julia gives w.
      {"formula_four_d",
       {{"preset_julia", "formula: {preset: julia, c: [-0.2, 0.6, 0.2, 0.2]}", 1.6},
        {"preset_julia_cubic_jacobian", "formula: {preset: julia, c: [-0.4, 0.5, 0.1, 0.1], degree: 3, slice: 0.2, de: jacobian}", 1.6},
        {"preset_quaternion", "quaternion: {iterations: 8}", 2.2},
        {"preset_hypercomplex", "hypercomplex: {iterations: 8}", 2.2},
        {"preset_aexion", "aexion: {iterations: 8}", 2.0},
        {"chain_hypercomplex_julia_w", "formula: {iterations: 8, bailout: 4, julia: [-0.3, 0.5, 0.1, 0.2], iterate: [hypercomplex, add_c]}", 1.6}},
       5.0},
      // Newton Pow3: the triplex Newton step between two inversions (the Jacobian through the step).
      {"formula_presets_newton",
       {{"preset_newton_pow3", "newton_pow3: {iterations: 8}", 2.0},
        {"preset_newton_pow3_c", "newton_pow3: {c: [-0.8, 0.3, 0.2], scale: 1.1, iterations: 8}", 2.0}},
       5.0, 2e-3, true},
      // The hybrid preset: a chain whose windows repeat every bulb_repeat + box_repeat iterations.
      {"formula_presets_hybrid",
       {{"preset_hybrid", "formula: {preset: hybrid, box_repeat: 2, iterations: 9}", 1.8},
        {"preset_hybrid_two_bulbs", "formula: {preset: hybrid, power: 5, bulb_repeat: 2, scale: -1.8, iterations: 8}", 1.8}},
       5.0},
      // The Generalized Fold Box and its polyhedral fold (face, edge and corner folds) with the scalar
      // derivative and the Jacobian.
      {"formula_presets_generalized_fold_box",
       {{"preset_generalized_fold_box", "generalized_fold_box: {scale: -1.5, iterations: 10}", 2.6},
        {"preset_generalized_fold_box_icosa", "generalized_fold_box: {generalized_fold_type: 5, scale: -1.5, iterations: 10}", 2.6},
        {"chain_polyhedral_jacobian",
         "formula: {iterations: 10, de: jacobian, iterate: [{polyhedral_fold: {type: dodecahedron}}, sphere_fold, {scale: -1.5}, add_c]}",
         2.6},
        {"chain_polyhedral_prism", "formula: {iterations: 10, iterate: [{polyhedral_fold: pentagonal_prism}, sphere_fold, {scale: 2}, add_c]}", 2.6}},
       7.0},
      // Amazing IFS: the tglad fold, scale / clamp(r^2), the rotation; without c and with it.
      {"formula_presets_amazing_ifs",
       {{"preset_amazing_ifs", "amazing_ifs: {scale: 2, fold_z: 1, iterations: 10}", 1.6},
        {"preset_amazing_ifs_c", "amazing_ifs: {scale: 1.8, rotation_axis: [1, 0, 1], rotation_angle: 20, add_c: 1, iterations: 10}", 2.2}},
       6.0},
  };
}

std::string group_yaml(const Group& g) {
  std::string y = "scene:\n  union:\n";
  for (size_t i = 0; i < g.members.size(); ++i)
    y += fmt::format("    - {{{}, translate: [{}, 0, 0]}}\n", g.members[i].node, i * g.spacing);
  return y;
}

// Float orbits of up to 12 folding/power iterations amplify float rounding
// by the per-step expansion (|scale| or the power) each iteration, so float
// and double orbits drift apart by ~1e-4 relative before the estimate is
// formed; the estimates are continuous in the orbit (folds are continuous
// maps), so the error stays proportional to |d|. Inside (d < 0, the fold
// fractals and the log estimators) only the rough size is reproducible.
// double: one float ulp of the stored result, as for the primitives.
Tolerance fractal_tolerance(bool dbl, double float_rel) {
  return dbl ? Tolerance{1e-9, 0x1p-23} : Tolerance{2e-4, float_rel, 5e-3, 0.5};
}

std::vector<V3> member_points(const ir::Module& m, const V3& centre, double radius, std::mt19937_64& rng) {
  std::vector<V3> pts;
  V3 lo = add(centre, {-radius, -radius, -radius}), hi = add(centre, {radius, radius, radius});
  for (int i = 0; i < 800; ++i) pts.push_back(test::uniform_in(rng, lo, hi));
  int rays = 0;
  for (int attempt = 0; attempt < 60 && rays < 8; ++attempt) {
    auto [o, rd] = test::random_ray(rng, centre, 1.8 * radius, 0.2 * radius);
    // The linear estimate r/|dr| of an IFS chain stays above about r/scale^iterations on its surface, so a ray
    // stops at a fraction of the radius, as a render's hit epsilon does.
    auto t = test::trace_to_surface([&](const V3& x) { return reference::distance(m, x); }, o, rd, 5e-4 * radius, 4 * radius);
    if (!t) continue;
    ++rays;
    for (int k = -60; k <= 60; ++k) pts.push_back(add(o, mul(rd, *t + k * 2e-4 * radius)));
  }
  for (int i = 0; i < 60; ++i) pts.push_back(add(centre, mul(test::random_unit(rng), radius * (1.0 + i * 0.02))));
  return pts;
}

class FractalConformance : public ::testing::TestWithParam<std::tuple<Group, EvalConfig>> {};

TEST_P(FractalConformance, MatchesReference) {
  const auto& [g, cfg] = GetParam();
  ir::Module m = test::compile_text(group_yaml(g), g.name + ".yaml", cfg.overrides());
  std::vector<V3> pts;
  std::vector<size_t> first;  // where each member's points start
  for (size_t i = 0; i < g.members.size(); ++i) {
    first.push_back(pts.size());
    // Seeded by the member's name: its sample does not change when members are added to its group.
    std::mt19937_64 rng(std::hash<std::string>{}(g.members[i].name) ^ 0xf7ac);
    auto mp = member_points(m, {double(i) * g.spacing, 0, 0}, g.members[i].radius, rng);
    ASSERT_GE(mp.size(), 1000u) << g.members[i].name << ": too few rays found the surface";
    pts.insert(pts.end(), mp.begin(), mp.end());
  }
  first.push_back(pts.size());
  Tolerance tol = fractal_tolerance(cfg.dbl, g.float_rel);
  tol.inside_sign = g.inside_sign;
  ProbeCheck pc = probe_and_compare(m, cfg, pts, tol);
  // Every member's sample must straddle its surface, or it says little.
  for (size_t i = 0; i < g.members.size(); ++i) {
    int near = 0;
    for (size_t k = first[i]; k < first[i + 1]; ++k) near += std::fabs(pc.ref_d[k]) < 1e-2 * g.members[i].radius;
    EXPECT_GT(near, 300) << g.members[i].name;
  }
}

INSTANTIATE_TEST_SUITE_P(Fractals, FractalConformance,
                         ::testing::Combine(::testing::ValuesIn(groups()), ::testing::ValuesIn(eval_configs())),
                         [](const auto& info) { return std::get<0>(info.param).name + "_" + std::get<1>(info.param).name(); });

// The inferred bounds must hold every point the estimator puts on or inside
// the surface (the render kernel clips rays to them). CPU only.
TEST(FractalBounds, SurfaceLiesInsideTheInferredBounds) {
  std::mt19937_64 rng(7);
  for (const auto& g : groups())
    for (const auto& mem : g.members) {
      ir::Module m = test::compile_text("scene: {" + mem.node + "}\n");
      const ir::Box3& b = m.graph->node(m.root).props.bounds;
      ASSERT_TRUE(b.finite()) << mem.name;
      double ext = 0;
      for (int i = 0; i < 3; ++i) ext = std::max(ext, b.hi[i] - b.lo[i]);
      ir::Box3 padded = b.padded(0.01 * ext);  // as the render kernel pads it
      std::vector<V3> pts;
      for (int i = 0; i < 20000; ++i)
        pts.push_back(test::uniform_in(rng, mul(V3{b.lo[0], b.lo[1], b.lo[2]}, 1.6), mul(V3{b.hi[0], b.hi[1], b.hi[2]}, 1.6)));
      int outside_hits = 0;
      for (const V3& p : pts) {
        if (reference::distance(m, p) > 1e-4 * ext) continue;
        bool in = true;
        for (int i = 0; i < 3; ++i) in = in && p[i] >= padded.lo[i] && p[i] <= padded.hi[i];
        outside_hits += !in;
      }
      EXPECT_EQ(outside_hits, 0) << mem.name << ": surface points outside the inferred bounds";
    }
}

}  // namespace
}  // namespace sdfc::conformance
