// Trap shapes and coloring sources are specialised: a scene holds the code
// of the shapes and sources its materials chose and nothing of the others,
// and a scene with the default trap holds what it held before shapes.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

std::string kernel_of(const std::string& scene, int width = 8) {
  return codegen::emit_opencl(passes::run_pipeline(test::lower_text(scene)), {width, false}).source;
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

std::string trap_scene(const std::string& node, const std::string& keys) {
  return "materials: {m: {orbit_trap: {palette: [[0, 0, 1], [1, 0.5, 0]]" + keys + "}}}\nscene: {" + node +
         ", material: m}\n";
}

const char* kMeasures[] = {"distance to the point", "distance to the plane", "distance to the line",
                           "distance to the sphere's shell"};

TEST(ColourCodegen, DefaultTrapHasNoShapeCode) {
  for (const char* node : {"mandelbulb: {power: 8}", "mandelbox: {}", "hybrid: {steps: [{mandelbulb: {power: 8}}]}"}) {
    std::string k = kernel_of(trap_scene(node, ""));
    EXPECT_EQ(k, kernel_of(trap_scene(node, ", shape: cross"))) << "cross is the default";
    EXPECT_FALSE(has(k, "orbit_trap_m")) << node;
    EXPECT_FALSE(has(k, "orbit-trap shapes")) << node;
    EXPECT_TRUE(has(k, "fmin(trap, fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z))))")) << node;
  }
}

TEST(ColourCodegen, OnlyTheChosenShapeIsEmitted) {
  const char* shapes[] = {"shape: point, point: [0, 0, 1]", "shape: plane, normal: [0, 1, 0]",
                          "shape: line, direction: [1, 0, 0]", "shape: sphere, radius: 0.5"};
  for (int s = 0; s < 4; ++s) {
    std::string k = kernel_of(trap_scene("mandelbox: {}", std::string(", ") + shapes[s]));
    for (int o = 0; o < 4; ++o) EXPECT_EQ(has(k, kMeasures[o]), o == s) << shapes[s] << " / " << kMeasures[o];
    EXPECT_TRUE(has(k, "inline real orbit_trap_m1(vec3 z)")) << shapes[s];
    EXPECT_TRUE(has(k, "trap_mandelbox_m1(p")) << shapes[s];
    EXPECT_FALSE(has(k, "inline real trap_mandelbox(")) << "the default copy is not needed";
    EXPECT_FALSE(has(k, "fmin(fabs(z.x), fmin(fabs(z.y), fabs(z.z)))")) << shapes[s];
  }
  // The hybrid writes its orbit inline: the measure is called there.
  std::string h = kernel_of(trap_scene("hybrid: {steps: [{mandelbulb: {power: 8}}]}", ", shape: point"));
  EXPECT_TRUE(has(h, "fmin(trap, orbit_trap_m1(z))"));
  // The quaternion Julia measures its 3D part.
  std::string q = kernel_of(trap_scene("julia: {c: [-0.2, 0.6, 0.2, 0.2]}", ", shape: sphere"));
  EXPECT_TRUE(has(q, "orbit_trap_m1(v3(a, v.x, v.y))"));
}

TEST(ColourCodegen, TwoMaterialsTwoShapes) {
  std::string k = kernel_of(
      "materials: {a: {orbit_trap: {palette: [[0, 0, 1], [1, 0.5, 0]], shape: point}},\n"
      "            b: {orbit_trap: {palette: [[0, 0, 1], [1, 0.5, 0]], shape: plane}}}\n"
      "scene: {union: [{mandelbox: {}, material: a}, {mandelbulb: {power: 8}, translate: [5, 0, 0], material: b}]}\n");
  EXPECT_TRUE(has(k, "trap_mandelbox_m1(p"));
  EXPECT_TRUE(has(k, "trap_mandelbulb_int_m2("));
  EXPECT_TRUE(has(k, kMeasures[0]));
  EXPECT_TRUE(has(k, kMeasures[1]));
  EXPECT_FALSE(has(k, kMeasures[2]));
}

TEST(ColourCodegen, ColoringCarriesOnlyItsSources) {
  const std::string pal = "palette: [[0, 0, 1], [1, 0.5, 0]]";
  auto scene = [&](const std::string& sources) {
    return "materials: {m: {coloring: {sources: [" + sources + "]}}}\nscene: {mandelbulb: {power: 8}, material: m}\n";
  };
  std::string normal = kernel_of(scene("{normal: {" + pal + "}}"));
  EXPECT_TRUE(has(normal, "source: normal"));
  EXPECT_TRUE(has(normal, "vec3 p, vec3 n)"));
  EXPECT_FALSE(has(normal, "scene_trap")) << "no orbit source: no orbit at the hit";
  std::string trap = kernel_of(scene("{trap: {" + pal + "}, weight: 2}, {position: {" + pal + "}}"));
  EXPECT_TRUE(has(trap, "scene_trap"));
  EXPECT_TRUE(has(trap, "source: trap, weight 0.6667"));
  EXPECT_TRUE(has(trap, "source: position, weight 0.3333"));
  EXPECT_FALSE(has(trap, "source: normal"));
  std::string only_trap = kernel_of(scene("{trap: {" + pal + "}}"));
  EXPECT_FALSE(has(only_trap, "vec3 p, vec3 n)")) << "the hit's point and normal only for the sources that read them";
  // Without coloring, none of it.
  std::string plain = kernel_of("materials: {m: {color: [1, 0, 0]}}\nscene: {mandelbulb: {power: 8}, material: m}\n");
  EXPECT_FALSE(has(plain, "coloring"));
  EXPECT_FALSE(has(plain, "vec3 p, vec3 n)"));
}

}  // namespace
}  // namespace sdfc
