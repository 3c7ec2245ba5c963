// The kernel holds only what the scene needs, with static values as literals
// and comments that lead back to the YAML.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

std::string kernel_of(const std::string& scene, int width = 1) {
  return codegen::emit_opencl(passes::run_pipeline(test::lower_text(scene)), {width, false}).source;
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

TEST(Specialisation, OnlyReachedStdlibFunctions) {
  std::string k = kernel_of("scene: {sphere: {radius: 1.25}}\n");
  EXPECT_TRUE(has(k, "inline real sd_sphere("));
  for (const char* absent : {"sd_torus", "sd_box", "sd_capsule", "sd_cylinder", "sd_plane", "de_mandelbulb",
                             "op_blend_polynomial", "normal_central"})
    EXPECT_FALSE(has(k, absent)) << absent;
  std::string t = kernel_of("scene: {torus: {major_radius: 1, minor_radius: 0.2}}\n");
  EXPECT_TRUE(has(t, "inline real sd_torus("));
  EXPECT_FALSE(has(t, "sd_sphere"));
}

TEST(Specialisation, DependenciesComeAlong) {
  std::string k = kernel_of("scene: {triangle: {a: [0, 0, 0], b: [1, 0, 0], c: [0, 1, 0]}}\n");
  EXPECT_TRUE(has(k, "inline real sd_triangle("));
  EXPECT_TRUE(has(k, "inline vec3 v3_cross("));  // sd_triangle calls it
  EXPECT_LT(k.find("inline vec3 v3_cross("), k.find("inline real sd_triangle("));
  EXPECT_FALSE(has(k, "inline real sd_quad("));  // a neighbour in its file, not reached
}

TEST(Specialisation, StaticValuesAreLiterals) {
  std::string k = kernel_of("scene: {sphere: {radius: 1.25}, translate: [0.5, 0, -2]}\n");
  EXPECT_TRUE(has(k, "sd_sphere(p0, 1.25f)")) << k;
  EXPECT_TRUE(has(k, "v3(0.5f, 0.0f, -2.0f)")) << k;
  std::string d = kernel_of("render: {precision: double}\nscene: {sphere: {radius: 0.1}}\n");
  EXPECT_TRUE(has(d, "sd_sphere(p, 0.1)")) << d;  // double literals carry no f
  EXPECT_TRUE(has(d, "cl_khr_fp64"));
}

TEST(Specialisation, CommentsCarryTheYamlLine) {
  std::string k = kernel_of("scene:\n  union:\n    - sphere: {radius: 1}\n    - box: {size: [1, 1, 1]}\n");
  EXPECT_TRUE(has(k, "// sphere radius=1  (t.yaml:3)")) << k;
  EXPECT_TRUE(has(k, "(t.yaml:4)")) << k;
}

TEST(Specialisation, NoMaterialCodeWithoutMaterials) {
  std::string k = kernel_of("scene:\n  union:\n    - sphere: {radius: 1}\n    - box: {size: [1, 1, 1]}\n");
  EXPECT_FALSE(has(k, "mask is1")) << k;  // no per-material selects
  std::string m = kernel_of("materials: {red: {color: [1, 0, 0]}}\nscene:\n  union:\n"
                            "    - {sphere: {radius: 1}, material: red}\n    - box: {size: [1, 1, 1]}\n");
  EXPECT_TRUE(has(m, "mask is1 = id == 1.0f;")) << m;
}

TEST(Specialisation, LightsAreUnrolledAndAmbientFolded) {
  std::string k = kernel_of(
      "lights:\n  - ambient: {color: [1, 1, 1], intensity: 0.25}\n  - ambient: {color: [1, 0, 0], intensity: 0.5}\n"
      "scene: {sphere: {radius: 1}}\n");
  EXPECT_TRUE(has(k, "v3(0.75f, 0.25f, 0.25f)")) << k;  // both ambients summed at compile time
  EXPECT_FALSE(has(k, "shade_blinn_phong")) << k;       // no direct light, no Phong code
}

TEST(Specialisation, BoundedScenesMarchInsideTheirBounds) {
  EXPECT_TRUE(has(kernel_of("scene: {sphere: {radius: 1}}\n"), "ray_box(ro, rd"));
  EXPECT_FALSE(has(kernel_of("scene: {plane: {normal: [0, 0, 1]}}\n"), "ray_box(ro, rd"));
}

TEST(Specialisation, WidthSelectsThePacketTypes) {
  std::string s = "scene: {sphere: {radius: 1}}\n";
  EXPECT_TRUE(has(kernel_of(s, 1), "typedef float real;"));
  EXPECT_TRUE(has(kernel_of(s, 16), "typedef float16 real;"));
  EXPECT_TRUE(has(kernel_of(s, 16), "typedef int16 mask;"));
  EXPECT_THROW(kernel_of(s, 3), std::invalid_argument);
  EXPECT_THROW(kernel_of(s, 128), std::invalid_argument);
}

TEST(Specialisation, WidePacketsOverloadOnlyTheBuiltinsTheKernelCalls) {
  // 64 lanes: Clang vectors of 64, whose halves are vectors of 32, whose halves are OpenCL's float16
  std::string sphere = kernel_of("scene: {sphere: {radius: 1}}\n", 64);
  EXPECT_TRUE(has(sphere, "typedef float real64 __attribute__((ext_vector_type(64)));")) << sphere;
  EXPECT_TRUE(has(sphere, "typedef float real32 __attribute__((ext_vector_type(32)));"));
  EXPECT_TRUE(has(sphere, "typedef real64 real;"));
  EXPECT_TRUE(has(sphere, "typedef mask64 mask;"));
  EXPECT_TRUE(has(sphere, "#define SDFC_PACKET_W 8"));  // 8x8 pixels
  EXPECT_TRUE(has(sphere, "OVERLOADED real64 sqrt(real64 a)"));
  EXPECT_TRUE(has(sphere, "OVERLOADED real64 select(real64 a, real64 b, mask64 c) { return c ? b : a; }"));
  EXPECT_TRUE(has(sphere, "OVERLOADED int any(mask64 a)"));
  for (const char* absent : {"atan2(", "fmod(", "acos(", "sinh("}) EXPECT_FALSE(has(sphere, absent)) << absent;
  // a scene that calls more builtins gets their overloads too
  std::string twist = kernel_of("scene:\n  box: {size: [1, 1, 1]}\n  twist: {axis: z, rate: 1.5}\n", 64);
  EXPECT_TRUE(has(twist, "OVERLOADED real64 cos(real64 a)")) << twist;
  // double precision: the masks are as wide as the lanes
  std::string dbl = kernel_of("render: {precision: double}\nscene: {sphere: {radius: 1}}\n", 32);
  EXPECT_TRUE(has(dbl, "typedef double real32 __attribute__((ext_vector_type(32)));")) << dbl;
  EXPECT_TRUE(has(dbl, "typedef long mask32 __attribute__((ext_vector_type(32)));"));
  EXPECT_TRUE(has(dbl, "#define SDFC_PACKET_H 4"));  // 8x4 pixels
}

}  // namespace
}  // namespace sdfc

namespace sdfc {
namespace {

// The scene function (after the stdlib) of a kernel.
std::string scene_part(const std::string& k) { return k.substr(k.find("// ---- scene distance")); }

// The text of one stdlib function in a kernel (its signature to its closing brace).
std::string function_text(const std::string& k, const std::string& name) {
  size_t at = k.find(name + "(");
  while (at != std::string::npos && k.rfind("inline", at) + 40 < at) at = k.find(name + "(", at + 1);
  if (at == std::string::npos) return "";
  return k.substr(at, k.find("\n}\n", at) - at);
}

// An integer Mandelbulb/Juliabulb power is iterated without any trig; other
// powers keep the trig formula (both are checked against the reference in
// the conformance suite).
TEST(Specialisation, IntegerMandelbulbPowerUsesNoTrig) {
  for (const char* scene : {"scene: {mandelbulb: {power: 8}}\n", "scene: {mandelbulb: {power: 5, julia: [0.3, 0, 0]}}\n"}) {
    std::string k = kernel_of(scene);
    EXPECT_TRUE(has(k, "de_mandelbulb_int(p")) << scene;
    for (const char* fn : {"de_mandelbulb_int", "fold_bulb_int", "cpow_int", "ipow_real"}) {
      std::string body = function_text(k, fn);
      ASSERT_FALSE(body.empty()) << fn;
      for (const char* trig : {"acos(", "atan2(", "sin(", "cos(", "pow("}) EXPECT_FALSE(has(body, trig)) << fn << " " << trig;
    }
    EXPECT_FALSE(has(k, "acos(")) << scene;
    EXPECT_FALSE(has(k, "atan2(")) << scene;
  }
  std::string real_power = kernel_of("scene: {mandelbulb: {power: 7.5}}\n");
  EXPECT_TRUE(has(scene_part(real_power), "de_mandelbulb(p"));
  EXPECT_TRUE(has(real_power, "acos("));
}

TEST(Specialisation, DeMethodPicksTheEstimator) {
  EXPECT_TRUE(has(scene_part(kernel_of("scene: {mandelbox: {de: jacobian}}\n")), "de_mandelbox_jacobian(p"));
  EXPECT_TRUE(has(scene_part(kernel_of("scene: {mandelbox: {de: dual}}\n")), "de_mandelbox_jacobian(p"));
  EXPECT_TRUE(has(scene_part(kernel_of("scene: {mandelbox: {}}\n")), "de_mandelbox(p"));
  std::string g = scene_part(kernel_of("scene: {mandelbulb: {de: gradient}}\n"));
  EXPECT_TRUE(has(g, "de_mandelbulb_numeric(p")) << g;
  EXPECT_TRUE(has(g, "/* de: gradient */")) << g;
  std::string f = scene_part(kernel_of("scene: {menger: {}, step_factor: 0.6}\n"));
  EXPECT_TRUE(has(f, "* 0.6f;  // step_factor")) << f;
}

}  // namespace
}  // namespace sdfc

namespace sdfc {
namespace {

// Orbit-trap colour is computed once per hit, by its own function, never in
// the march: scene_dist (what the march calls) has no trap code.
TEST(Specialisation, OrbitTrapOnlyAtTheHit) {
  std::string k = codegen::emit_opencl(passes::run_pipeline(test::lower_text(
      "materials: {glow: {orbit_trap: {palette: [[0, 0, 1], [1, 0.5, 0]], mix: 0.6}}}\n"
      "scene: {union: [{mandelbox: {}, material: glow}, {sphere: {radius: 1}, translate: [9, 0, 0]}]}\n")), {1, false}).source;
  size_t dist = k.find("real scene_dist_inline(TIME_PARAM vec3 p, mask live)"), dist_end = k.find("\n}\n", dist);
  ASSERT_NE(dist, std::string::npos);
  EXPECT_EQ(k.substr(dist, dist_end - dist).find("trap"), std::string::npos);
  EXPECT_NE(k.find("real scene_trap(TIME_PARAM vec3 p)"), std::string::npos);
  EXPECT_NE(k.find("trap_mandelbox(p"), std::string::npos);
  EXPECT_NE(k.find("real trap = scene_trap(TIME_ARG pos);"), std::string::npos);
  EXPECT_NE(k.find("v3_mix(*albedo, pal, (real)(0.6f))"), std::string::npos) << k;
  // Without an orbit-trap material there is no trap code at all.
  std::string plain = codegen::emit_opencl(passes::run_pipeline(test::lower_text("scene: {mandelbox: {}}\n")), {1, false}).source;
  EXPECT_EQ(plain.find("trap"), std::string::npos);
}

}  // namespace
}  // namespace sdfc

namespace sdfc {
namespace {

std::string kernel_for(const std::string& scene) {
  return codegen::emit_opencl(passes::run_pipeline(test::lower_text(
                                  "materials: {red: {color: [1, 0, 0]}, blue: {color: [0, 0, 1]},\n"
                                  "            pal: {orbit_trap: {palette: [[0, 0, 1], [1, 0.5, 0]]}}}\n" +
                                  scene)),
                              {8, false})
      .source;
}

// Materials mix across a smooth blend only where its children show
// different materials: every other kernel keeps the material id and holds
// no blend code; the march (scene_dist) never holds it.
TEST(Specialisation, MaterialBlendOnlyForSmoothBlendsOfDifferentMaterials) {
  const char* blend_code[] = {"scene_material", "mat_record", "mat_mix", "op_weight_"};
  const std::string red = "{sphere: {radius: 1}, material: red}";
  const std::string blue = "{sphere: {radius: 1}, translate: [1, 0, 0], material: blue}";
  const std::string grey = "{box: {}, translate: [0, 1, 0]}";
  for (const std::string& scene : {
           "scene: {union: [" + red + ", " + blue + "]}\n",                            // hard union
           "scene: {smooth_union: {radius: 0.3, children: [" + red + ", " + red + "]}}\n",  // one material
           "scene: {smooth_union: {radius: 0.3, children: [{sphere: {radius: 1}}, " + grey + "]}, material: blue}\n",
           "scene: {chamfer_union: {radius: 0.3, children: [" + red + ", " + blue + "]}}\n",  // stylised: nearer child
           "scene: {union: [{smooth_union: {radius: 0.3, children: [" + red + ", " + red + "]}}, " + blue + "]}\n",
       }) {
    std::string k = kernel_for(scene);
    for (const char* c : blend_code) EXPECT_EQ(k.find(c), std::string::npos) << c << " in the kernel of\n" << scene;
    // the material id comes from the scene, or is a literal where every hit has one material
    EXPECT_TRUE(k.find("scene_dist_mat(TIME_ARG pos, &id)") != std::string::npos ||
                k.find("the scene's one material") != std::string::npos)
        << scene;
  }
  for (const std::string& scene : {
           "scene: {smooth_union: {radius: 0.3, children: [" + red + ", " + blue + "]}}\n",
           "scene: {smooth_difference: {radius: 0.3, kind: cubic, children: [" + red + ", " + grey + "]}}\n",
           "scene: {smooth_intersection: {radius: 0.3, kind: exponential, children: [" + blue + ", " + grey + "]}}\n",
           // one orbit-trap material, two fractals: each has its own trap colour
           std::string("scene: {smooth_union: {radius: 0.3, children: [{mandelbulb: {}}, {mandelbox: {}, translate: [3, 0, 0]}]},"
                       " material: pal}\n"),
       }) {
    std::string k = kernel_for(scene);
    for (const char* c : blend_code) EXPECT_NE(k.find(c), std::string::npos) << c << " missing in the kernel of\n" << scene;
    size_t dist = k.find("real scene_dist_inline(TIME_PARAM vec3 p, mask live)"), dist_end = k.find("\n}\n", dist);
    ASSERT_NE(dist, std::string::npos);
    EXPECT_EQ(k.substr(dist, dist_end - dist).find("mat_"), std::string::npos) << "blend code in the march";
    EXPECT_EQ(k.find("scene_dist_mat(TIME_ARG pos, &id)"), std::string::npos) << scene;
  }
}

}  // namespace
}  // namespace sdfc
