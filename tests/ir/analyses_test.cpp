// The analyse pass: what it records on the module for the emitters, and
// that those facts still hold after the passes that follow it.
#include <gtest/gtest.h>

#include <stdexcept>

#include "scene_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/analyses.hpp"
#include "sdfc/ir/fractal_math.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

ir::Analyses facts(const std::string& yaml) {
  ir::Module m = passes::run_pipeline(test::lower_text(yaml));
  EXPECT_TRUE(m.analyses.known);
  return m.analyses;
}

const char* kTwoMaterials = "materials: {red: {color: [1, 0, 0]}, blue: {color: [0, 0, 1]}}\n";

TEST(Analyse, TimeIsUsedByAnimatedGeometryLightsAndFog) {
  EXPECT_FALSE(facts("scene: {sphere: {radius: 1}}\n").uses_time);
  EXPECT_TRUE(facts("scene: {sphere: {radius: \"1 + 0.1*sin(time)\"}}\n").uses_time);
  EXPECT_TRUE(facts("lights: [{directional: {direction: [0, 0, -1], intensity: \"1 + 0.5*sin(time)\"}}]\n"
                    "scene: {sphere: {radius: 1}}\n")
                  .uses_time);
  EXPECT_TRUE(facts("effects: {fog: {color: [1, 1, 1], density: \"0.05 + 0.01*sin(time)\"}}\n"
                    "scene: {sphere: {radius: 1}}\n")
                  .uses_time);
}

TEST(Analyse, MaterialsBlendOnlyWhereASmoothBlendJoinsDifferentOnes) {
  std::string pair = "        children:\n"
                     "          - {sphere: {radius: 0.5}, translate: [-0.3, 0, 0], material: red}\n"
                     "          - {sphere: {radius: 0.5}, translate: [0.3, 0, 0], material: MAT}\n";
  auto scene = [&](const std::string& op, const std::string& second) {
    std::string kids = pair;
    kids.replace(kids.find("MAT"), 3, second);
    return std::string(kTwoMaterials) + "scene:\n  union:\n    - " + op + ":\n        radius: 0.2\n" + kids;
  };
  EXPECT_TRUE(facts(scene("smooth_union", "blue")).material_blend);
  EXPECT_FALSE(facts(scene("smooth_union", "red")).material_blend);  // one material: nothing to mix
  EXPECT_FALSE(facts(std::string(kTwoMaterials) +  // a hard union selects
                     "scene:\n  union:\n    - {sphere: {radius: 0.5}, translate: [-0.3, 0, 0], material: red}\n"
                     "    - {sphere: {radius: 0.5}, translate: [0.3, 0, 0], material: blue}\n")
                   .material_blend);
}

TEST(Analyse, OrbitTrapsAndTheUniformMaterial) {
  ir::Analyses trap = facts("materials: {glow: {color: [1, 1, 1], orbit_trap: {palette: [[0, 0, 0], [1, 1, 1]]}}}\n"
                            "scene: {mandelbulb: {power: 8}, material: glow}\n");
  EXPECT_TRUE(trap.orbit_traps);
  ASSERT_TRUE(trap.uniform_material.has_value());
  EXPECT_EQ(*trap.uniform_material, 1.0);  // 0 is the default material
  ir::Analyses plain = facts(std::string(kTwoMaterials) +
                             "scene:\n  union:\n    - {sphere: {radius: 1}, material: red}\n"
                             "    - {box: {size: [1, 1, 1]}, translate: [3, 0, 0], material: blue}\n");
  EXPECT_FALSE(plain.orbit_traps);
  EXPECT_FALSE(plain.uniform_material.has_value());
}

TEST(Analyse, RaysMarchInTheBoundsAndInALoneBulbsBall) {
  EXPECT_FALSE(facts("scene: {plane: {normal: [0, 0, 1]}}\n").ray_bounds.has_value());
  ir::Analyses sphere = facts("scene: {sphere: {radius: 1}}\n");
  ASSERT_TRUE(sphere.ray_bounds.has_value());
  EXPECT_FALSE(sphere.ray_bounds->has_sphere);
  EXPECT_NEAR(sphere.ray_bounds->box.hi[0], 1 + 0.02 + 1e-3, 1e-12);  // padded by 1% of the extent and a little
  ir::Analyses bulb = facts("scene: {mandelbulb: {power: 8, iterations: 6}}\n");
  ASSERT_TRUE(bulb.ray_bounds.has_value());
  ASSERT_TRUE(bulb.ray_bounds->has_sphere);
  EXPECT_DOUBLE_EQ(bulb.ray_bounds->radius, ir::mandelbulb_set_radius(8) * 1.01 + 1e-3);
  // An animated power: the ball holds the set at every time, not only at 0.
  ir::Analyses moving = facts("scene: {mandelbulb: {power: \"8 - 6*abs(sin(time))\", iterations: 6}}\n");
  ASSERT_TRUE(moving.ray_bounds && moving.ray_bounds->has_sphere);
  EXPECT_GT(moving.ray_bounds->radius, bulb.ray_bounds->radius);
  EXPECT_FALSE(facts("scene: {mandelbulb: {power: 8}, translate: [1, 0, 0]}\n").ray_bounds->has_sphere);
}

// analyse runs before insert_bounding_volumes; the box tests it inserts
// must leave every fact as it was.
TEST(Analyse, FactsHoldAfterBoundingVolumes) {
  for (const char* yaml : {"scene: {mandelbulb: {power: 8}}\n",
                           "materials: {red: {color: [1, 0, 0]}}\nscene:\n  smooth_union:\n    radius: 0.3\n"
                           "    children:\n      - {mandelbox: {}, material: red}\n      - {sphere: {radius: 1}}\n"}) {
    ir::Module m = passes::run_pipeline(test::lower_text(yaml));
    ir::Analyses again = passes::analyse(m).analyses;
    EXPECT_EQ(again.uses_time, m.analyses.uses_time) << yaml;
    EXPECT_EQ(again.material_blend, m.analyses.material_blend) << yaml;
    EXPECT_EQ(again.orbit_traps, m.analyses.orbit_traps) << yaml;
    EXPECT_EQ(again.uniform_material, m.analyses.uniform_material) << yaml;
    ASSERT_EQ(again.ray_bounds.has_value(), m.analyses.ray_bounds.has_value()) << yaml;
    if (again.ray_bounds) {
      EXPECT_EQ(again.ray_bounds->box.lo, m.analyses.ray_bounds->box.lo) << yaml;
      EXPECT_EQ(again.ray_bounds->box.hi, m.analyses.ray_bounds->box.hi) << yaml;
      EXPECT_EQ(again.ray_bounds->radius, m.analyses.ray_bounds->radius) << yaml;
    }
  }
}

TEST(Analyse, TheEmitterRefusesAModuleWithoutIt) {
  ir::Module m = test::lower_text("scene: {sphere: {radius: 1}}\n");
  for (const auto& pass : passes::pipeline())
    if (pass.name != "analyse") m = pass.run(std::move(m));
  EXPECT_THROW(codegen::emit_opencl(m, {1, false}), std::logic_error);
  EXPECT_NO_THROW(codegen::emit_opencl(passes::analyse(std::move(m)), {1, false}));
}

}  // namespace
}  // namespace sdfc
