// Formula chains on the CPU: the estimator the compiler picks for a chain,
// repeats and windows, and the chain's double reference against the
// built-in fractals it spells out (written independently in reference/).
// Presets: a preset's own node is the formula naming it, the built-ins'
// presets are the built-in kinds' fields and render with the kinds' code
// where the kind draws them, `sdfc check`'s account names them.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>
#include <string>

#include "scene_text.hpp"
#include "sdfc/formula/chain.hpp"
#include "sdfc/formula/evaluate.hpp"
#include "sdfc/formula/preset.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc {
namespace {

ir::Module module_of(const std::string& node) { return passes::run_pipeline(test::lower_text("scene: " + node + "\n")); }

// The chain a module's fractal stands for: the formula node's, or the one a
// preset drawn by its built-in kind's code noted at the kind's node.
size_t index_of(const ir::Module& m) {
  for (ir::NodeId k : m.graph->postorder(m.root)) {
    const ir::Node& n = m.graph->node(k);
    if (n.kind == ir::Kind::Formula) return size_t(n.params[0]);
    if (auto c = formula::builtin_chain_at(n.loc)) return *c;
  }
  throw std::runtime_error("no formula node");
}
bool has_kind(const ir::Module& m, ir::Kind kind) {
  for (ir::NodeId k : m.graph->postorder(m.root))
    if (m.graph->node(k).kind == kind) return true;
  return false;
}
const formula::Chain& chain_of(const ir::Module& m) { return formula::chain(index_of(m)); }

formula::Plan plan_of(const std::string& node) { return formula::plan(chain_of(module_of(node))); }

TEST(FormulaPlan, FoldsAndUniformScalesKeepAScalarDerivativeAndTheLinearForm) {
  formula::Plan p = plan_of("{formula: {iterate: [box_fold, sphere_fold, {scale: 2}, {rotate: {angle: 30}}, add_c]}}");
  EXPECT_FALSE(p.jacobian);
  EXPECT_FALSE(p.log);
}

TEST(FormulaPlan, ANonConformalStepTakesTheJacobianAndIsNamed) {
  formula::Plan p = plan_of("{formula: {iterate: [box_fold, {scale_xyz: [1, 2, 1]}, add_c]}}");
  EXPECT_TRUE(p.jacobian);
  EXPECT_NE(p.why.find("scale_xyz"), std::string::npos) << p.why;
  // equal factors are a uniform scale
  EXPECT_FALSE(plan_of("{formula: {iterate: [box_fold, {scale_xyz: [2, -2, 2]}, add_c]}}").jacobian);
}

TEST(FormulaPlan, APowerStepTakesTheLogForm) {
  formula::Plan p = plan_of("{formula: {iterate: [{bulb_power: 8}, add_c]}}");
  EXPECT_TRUE(p.log);
  EXPECT_FALSE(p.jacobian);
  EXPECT_NE(p.why.find("bulb_power"), std::string::npos) << p.why;
}

TEST(FormulaPlan, ExprIsDifferentiatedAndOnlyANonLinearOneIsAPower) {
  formula::Plan lin = plan_of("{formula: {iterate: [{expr: {x: \"2*x + y\", y: \"2*y\", z: \"2*z - cx\"}}, add_c]}}");
  EXPECT_TRUE(lin.jacobian);
  EXPECT_FALSE(lin.log);
  formula::Plan sq = plan_of("{formula: {iterate: [{expr: {x: \"x*x - y*y\", y: \"2*x*y\"}}, add_c]}}");
  EXPECT_TRUE(sq.jacobian);
  EXPECT_TRUE(sq.log);
}

TEST(FormulaPlan, DeOverridesTheChoice) {
  EXPECT_TRUE(plan_of("{formula: {de: jacobian, iterate: [{bulb_power: 8}, add_c]}}").jacobian);
  EXPECT_FALSE(plan_of("{formula: {de: linear, iterate: [{bulb_power: 8}, add_c]}}").log);
  EXPECT_TRUE(plan_of("{formula: {de: log, iterate: [box_fold, {scale: 2}, add_c]}}").log);
}

TEST(FormulaChain, RepeatsUnrollAndRepeatFromCountsEntries) {
  ir::Module m = module_of("{formula: {repeat_from: 1, iterate: [{scale: {scale: 2, repeat: 3}}, box_fold, {add_c: {from: 1, until: 4}}]}}");
  const formula::Chain& c = chain_of(m);
  ASSERT_EQ(c.steps.size(), 5u);
  EXPECT_EQ(c.repeat_from, 3);  // entry 1 (box_fold) is step 3 after the three scales
  EXPECT_EQ(c.steps[4].from, 1);
  EXPECT_EQ(c.steps[4].until, 4);
}

// The chain's reference against the built-in kind's, point by point. A
// preset the kind draws renders as the kind: its chain is compared.
void expect_same_field(const std::string& chain, const std::string& builtin, double radius, double tol) {
  ir::Module a = module_of(chain);
  const bool drawn_by_kind = !has_kind(a, ir::Kind::Formula);
  const formula::Chain& c = formula::chain(index_of(a));
  ir::Module b = module_of(builtin);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-radius, radius);
  int compared = 0;
  for (int i = 0; i < 4000; ++i) {
    reference::Vec3 p{u(rng), u(rng), u(rng)};
    double da = drawn_by_kind ? formula::evaluate(c, p).distance : reference::distance(a, p);
    double db = reference::distance(b, p);
    if (std::fabs(db) > 0.5 * radius) continue;  // far field: the two bound differently there
    ++compared;
    ASSERT_NEAR(da, db, tol * std::max(1.0, std::fabs(db))) << chain << " at " << p[0] << ", " << p[1] << ", " << p[2];
  }
  EXPECT_GT(compared, 2000);
}

TEST(FormulaChain, MandelboxChainIsTheMandelbox) {
  expect_same_field("{formula: {iterations: 12, iterate: [box_fold, sphere_fold, {scale: -1.5}, add_c]}}",
                    "{mandelbox: {scale: -1.5, iterations: 12}, step_factor: 1}", 2.0, 1e-9);
}

TEST(FormulaChain, JuliaMandelboxChainIsTheJuliaMandelbox) {
  expect_same_field("{formula: {iterations: 10, julia: [0.8, -0.4, 0.3], iterate: [box_fold, sphere_fold, {scale: 2}, add_c]}}",
                    "{mandelbox: {scale: 2, julia: [0.8, -0.4, 0.3], iterations: 10}, step_factor: 1}", 2.0, 1e-9);
}

TEST(FormulaChain, NonConformalMandelboxChainIsTheJacobianMandelbox) {
  expect_same_field(
      "{formula: {iterations: 12, iterate: [box_fold, sphere_fold, {scale: -1.5}, {scale_xyz: [1.2, 1.0, 0.8]}, add_c]}}",
      "{mandelbox: {scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], iterations: 12, de: jacobian}}", 2.0, 1e-9);
}

TEST(FormulaPreset, MandelboxPresetIsTheMandelbox) {
  expect_same_field("{formula: {preset: mandelbox, scale: -1.5, iterations: 12}}",
                    "{mandelbox: {scale: -1.5, iterations: 12}, step_factor: 1}", 2.0, 1e-9);
}

TEST(FormulaPreset, NonConformalMandelboxPresetIsTheJacobianMandelbox) {
  expect_same_field("{formula: {preset: mandelbox, scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], iterations: 12}}",
                    "{mandelbox: {scale: -1.5, scale_xyz: [1.2, 1.0, 0.8], iterations: 12, de: jacobian}}", 2.0, 1e-9);
}

TEST(FormulaPreset, MandelboxPresetParametersAreTheMandelboxs) {
  expect_same_field("{formula: {preset: mandelbox, scale: 2.2, folding_limit: 1.1, min_radius: 0.4, fixed_radius: 1.2, iterations: 10}}",
                    "{mandelbox: {scale: 2.2, folding_limit: 1.1, min_radius: 0.4, fixed_radius: 1.2, iterations: 10}, step_factor: 1}", 2.0, 1e-9);
}

TEST(FormulaPreset, JuliaMandelboxPresetIsTheJuliaMandelbox) {
  expect_same_field("{formula: {preset: mandelbox, scale: 2, julia: [0.8, -0.4, 0.3], iterations: 10}}",
                    "{mandelbox: {scale: 2, julia: [0.8, -0.4, 0.3], iterations: 10}, step_factor: 1}", 2.0, 1e-9);
}

TEST(FormulaPreset, MandelbulbPresetIsTheMandelbulb) {
  // inside the cube of 0.9 (|p| < 1.56): the built-in's far-field bound
  // starts at 1.5 times its set radius (1.66), the chain's at twice the bailout
  expect_same_field("{formula: {preset: mandelbulb, power: 8}}", "{mandelbulb: {power: 8}, step_factor: 1}", 0.9, 1e-6);
}

// The kind draws the preset when it can: the same node as the kind written
// out; a setting only a chain has, or a value outside the kind's ranges,
// keeps the chain.
TEST(FormulaPreset, ABuiltInsPresetRendersAsTheKindWhereTheKindDrawsIt) {
  auto same_module = [](const std::string& a, const std::string& b) {
    return ir::print(module_of(a)) == ir::print(module_of(b));
  };
  EXPECT_TRUE(same_module("{formula: {preset: mandelbox, scale: -1.5, iterations: 12}}",
                          "{mandelbox: {scale: -1.5, iterations: 12}}"));
  EXPECT_TRUE(same_module("{formula: {preset: mandelbulb, power: 7, julia: [0.3, 0.1, -0.2]}}",
                          "{mandelbulb: {power: 7, julia: [0.3, 0.1, -0.2]}}"));
  EXPECT_TRUE(same_module("{menger_sponge: {iterations: 6}}", "{menger: {scale: 3, iterations: 6}}"));
  EXPECT_TRUE(same_module("{formula: {preset: sierpinski, scale: 2.5}}", "{sierpinski: {scale: 2.5, iterations: 16}}"));
  EXPECT_TRUE(same_module("{kaleidoscopic_ifs: {iterations: 9}}",
                          "{kifs: {symmetry: octahedral, scale: 3, offset: [1, 1, 1], iterations: 9}}"));
  for (const char* chain : {"{formula: {preset: mandelbox, de: jacobian}}", "{formula: {preset: mandelbox, bailout: 50}}",
                            "{formula: {preset: mandelbox, iterations: 300}}", "{menger_sponge: {offset: [1, 1, 0.5]}}",
                            "{menger_sponge: {scale: 5}}", "{kaleidoscopic_ifs: {rotation_angle: 20}}",
                            "{formula: {preset: mandelbulb, de: linear}}", "{formula: {preset: sierpinski, iterations: 40}}"}) {
    SCOPED_TRACE(chain);
    EXPECT_TRUE(has_kind(module_of(chain), ir::Kind::Formula));
  }
}

TEST(FormulaPreset, ANodeOfItsOwnIsTheFormulaNamingIt) {
  EXPECT_EQ(index_of(module_of("{pseudo_kleinian: {min_r2: 0.4, iterations: 9}}")),
            index_of(module_of("{formula: {preset: pseudo_kleinian, min_r2: 0.4, iterations: 9}}")));
  EXPECT_NE(index_of(module_of("{pseudo_kleinian: {min_r2: 0.4}}")), index_of(module_of("{pseudo_kleinian: {min_r2: 0.3}}")));
}

TEST(FormulaPreset, TheAccountNamesThePresetItsStepsAndItsEstimator) {
  const formula::Chain& c = formula::chain(index_of(module_of("{pseudo_kleinian: {box_size: [0.6, 0.7, 0.8]}}")));
  std::string text = formula::describe(c);
  EXPECT_NE(text.find("preset pseudo_kleinian"), std::string::npos) << text;
  EXPECT_NE(text.find("surf_fold limit [0.6, 0.7, 0.8]"), std::string::npos) << text;
  EXPECT_NE(text.find("kleinian_fold"), std::string::npos) << text;
  EXPECT_TRUE(formula::plan(c).kleinian) << text;
  // a scene's de: overrides the preset's own
  EXPECT_FALSE(formula::plan(formula::chain(index_of(module_of("{pseudo_kleinian: {de: linear}}")))).kleinian);
}

// The defaults a preset documents are the ones it reads: a preset written
// with every parameter at its default is the bare preset.
TEST(FormulaPreset, EveryPresetBuildsFromItsDefaults) {
  for (const formula::Preset* p : formula::presets()) {
    SCOPED_TRACE(std::string(p->name));
    std::string body;
    for (const formula::PresetParam& q : p->params) {
      body += body.empty() ? "" : ", ";
      body += q.width == 1   ? fmt::format("{}: {}", q.name, q.fallback[0])
              : q.width == 4 ? fmt::format("{}: [{}, {}, {}, {}]", q.name, q.fallback[0], q.fallback[1], q.fallback[2], q.fallback[3])
                             : fmt::format("{}: [{}, {}, {}]", q.name, q.fallback[0], q.fallback[1], q.fallback[2]);
    }
    const std::string bare = fmt::format("{{formula: {{preset: {}}}}}", p->name);
    const std::string full = fmt::format("{{formula: {{preset: {}{}{}}}}}", p->name, body.empty() ? "" : ", ", body);
    const formula::Chain& c = formula::chain(index_of(module_of(bare)));
    EXPECT_EQ(c.iterations, p->iterations);
    EXPECT_FALSE(c.steps.empty());
    EXPECT_EQ(index_of(module_of(full)), index_of(module_of(bare)));
  }
}

}  // namespace
}  // namespace sdfc
