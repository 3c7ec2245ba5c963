// Presets: a preset is its chain (the node form and the `formula: {preset}`
// form give the same one), the built-ins' presets are the built-in kinds'
// fields, and `sdfc check`'s account names the preset and its steps.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <random>
#include <string>

#include "scene_text.hpp"
#include "sdfc/formula/chain.hpp"
#include "sdfc/formula/preset.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc {
namespace {

ir::Module module_of(const std::string& node) { return passes::run_pipeline(test::lower_text("scene: " + node + "\n")); }

size_t chain_index(const ir::Module& m) {
  for (ir::NodeId k : m.graph->postorder(m.root))
    if (m.graph->node(k).kind == ir::Kind::Formula) return size_t(m.graph->node(k).params[0]);
  throw std::runtime_error("no formula node");
}

void expect_same_field(const std::string& a_text, const std::string& b_text, double radius, double tol) {
  ir::Module a = module_of(a_text), b = module_of(b_text);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-radius, radius);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    reference::Vec3 p{u(rng), u(rng), u(rng)};
    double da = reference::distance(a, p), db = reference::distance(b, p);
    if (std::fabs(db) > 0.5 * radius) continue;
    ++compared;
    ASSERT_NEAR(da, db, tol * std::max(1.0, std::fabs(db))) << a_text << " at " << p[0] << ", " << p[1] << ", " << p[2];
  }
  EXPECT_GT(compared, 1000);
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

TEST(FormulaPreset, ANodeOfItsOwnIsTheFormulaNamingIt) {
  EXPECT_EQ(chain_index(module_of("{pseudo_kleinian: {min_r2: 0.4, iterations: 9}}")),
            chain_index(module_of("{formula: {preset: pseudo_kleinian, min_r2: 0.4, iterations: 9}}")));
  EXPECT_NE(chain_index(module_of("{pseudo_kleinian: {min_r2: 0.4}}")), chain_index(module_of("{pseudo_kleinian: {min_r2: 0.3}}")));
}

TEST(FormulaPreset, TheAccountNamesThePresetItsStepsAndItsEstimator) {
  const formula::Chain& c = formula::chain(chain_index(module_of("{pseudo_kleinian: {box_size: [0.6, 0.7, 0.8]}}")));
  std::string text = formula::describe(c);
  EXPECT_NE(text.find("preset pseudo_kleinian"), std::string::npos) << text;
  EXPECT_NE(text.find("surf_fold limit [0.6, 0.7, 0.8]"), std::string::npos) << text;
  EXPECT_NE(text.find("kleinian_fold"), std::string::npos) << text;
  EXPECT_TRUE(formula::plan(c).kleinian) << text;
  // a scene's de: overrides the preset's own
  EXPECT_FALSE(formula::plan(formula::chain(chain_index(module_of("{pseudo_kleinian: {de: linear}}")))).kleinian);
}

// The defaults a preset documents are the ones it reads: a preset written
// with every parameter at its default is the bare preset.
TEST(FormulaPreset, EveryPresetBuildsFromItsDefaults) {
  for (const formula::Preset* p : formula::presets()) {
    SCOPED_TRACE(std::string(p->name));
    std::string body;
    for (const formula::PresetParam& q : p->params) {
      body += body.empty() ? "" : ", ";
      body += q.width == 1 ? fmt::format("{}: {}", q.name, q.fallback[0])
                           : fmt::format("{}: [{}, {}, {}]", q.name, q.fallback[0], q.fallback[1], q.fallback[2]);
    }
    const std::string bare = fmt::format("{{formula: {{preset: {}}}}}", p->name);
    const std::string full = fmt::format("{{formula: {{preset: {}{}{}}}}}", p->name, body.empty() ? "" : ", ", body);
    const formula::Chain& c = formula::chain(chain_index(module_of(bare)));
    EXPECT_EQ(c.iterations, p->iterations);
    EXPECT_FALSE(c.steps.empty());
    EXPECT_EQ(chain_index(module_of(full)), chain_index(module_of(bare)));
  }
}

}  // namespace
}  // namespace sdfc
