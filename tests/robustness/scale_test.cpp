// Very deep and very wide scenes: they compile or are refused with a
// message; nothing overflows the stack or hangs.
#include <gtest/gtest.h>

#include <filesystem>
#include <sdfrt/device.hpp>
#include <sdfrt/renderer.hpp>

#include "run_sdfc.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::test {
namespace {

// `depth` unions nested in flow style, a sphere at the bottom.
std::string nested_unions(int depth) {
  std::string s = "scene: ";
  for (int i = 0; i < depth; ++i) s += "{union: [";
  s += "{sphere: {radius: 1}}";
  for (int i = 0; i < depth; ++i) s += "]}";
  return s + "\n";
}

// n spheres on a grid in one union, block style (one line per sphere).
std::string wide_union(int n, const std::string& shape = "sphere: {radius: 0.4}") {
  std::string s = "scene:\n  union:\n";
  for (int i = 0; i < n; ++i)
    s += "    - {" + shape + ", translate: [" + std::to_string(i % 100) + ", " + std::to_string(i / 100) + ", 0]}\n";
  return s;
}

TEST(Scale, TenThousandNestedUnionsAreRefusedWithAMessage) {
  ScratchDir dir;
  RunResult r = run_sdfc("check " + dir.write("deep.yaml", nested_unions(10000)));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("deep.yaml:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the scene nests deeper than 200 levels"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("flatten it"), std::string::npos) << r.err;
}

TEST(Scale, DeepestAllowedNestingCompilesEmitsAndEvaluates) {
  // Each union level is two YAML levels (map, list): 95 unions fit under 200.
  SourceValue doc = load_yaml_text(nested_unions(95), "deep.yaml");
  ir::Module m = build_module(doc, "deep.yaml");
  EXPECT_FALSE(ir::print(m).empty());
  auto k = codegen::emit_opencl(m, {16, false});
  EXPECT_NE(k.source.find("sd_sphere"), std::string::npos);
  EXPECT_NEAR(reference::distance(m, {3, 0, 0}), 2.0, 1e-12);
}

TEST(Scale, BlockStyleNestingPastTheCapIsRefused) {
  std::string s = "scene:\n  union:\n";
  std::string indent = "    ";
  for (int i = 0; i < 150; ++i, indent += "    ") s += indent + "- union:\n";
  s += indent + "- sphere: {radius: 1}\n";
  try {
    load_yaml_text(s, "deep.yaml");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("nests deeper than 200 levels"), std::string::npos) << e.what();
  }
}

TEST(Scale, AliasBombIsRefusedQuickly) {
  std::string s = "a0: &a0 [1, 1]\n";
  for (int i = 1; i < 40; ++i)
    s += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
         std::to_string(i - 1) + "]\n";
  s += "scene: {sphere: {radius: 1}}\n";
  try {
    load_yaml_text(s, "laughs.yaml");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("once its aliases (*name) are expanded"), std::string::npos) << e.what();
  }
}

TEST(Scale, TenThousandSpheresAreAcceptedAsData) {
  ScratchDir dir;
  RunResult r = run_sdfc("check " + dir.write("wide.yaml", wide_union(10000)));
  EXPECT_EQ(r.code, 0) << r.err;  // one object set (tests/objects)
}

TEST(Scale, TenThousandToriAreRefusedWithTheLimit) {
  ScratchDir dir;
  RunResult r = run_sdfc("check " + dir.write("wide.yaml", wide_union(10000, "torus: {major_radius: 0.3, minor_radius: 0.1}")));
  EXPECT_EQ(r.code, 1) << r.err;
  // 10 000 translations and one shared torus (not held as data), a union (and
  // a translation by [0, 0, 0] unless the passes fold it away).
  EXPECT_NE(r.err.find("wide.yaml:2:3: error: the scene makes a kernel of 200"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node evaluations, more than the limit of 4096"), std::string::npos) << r.err;
}

TEST(Scale, TwoThousandSpheresCompileAndEvaluate) {
  SourceValue doc = load_yaml_text(wide_union(2000), "wide.yaml");
  ir::Module m = build_module(doc, "wide.yaml");
  // 2000 spheres as one object set (and a box test in front of it): the kernel holds their numbers as data.
  EXPECT_LE(ir::count_nodes(m), 2u);
  auto k = codegen::emit_opencl(m, {16, false});
  EXPECT_LT(k.source.size(), 48000u);  // the walk, the cone, its list and the hits shaded from it: about 41 kB, whatever the count
  EXPECT_GT(k.scene_data.size(), 2000u * 8);
  // The sphere at grid cell (37, 12) is 0.4 across: its centre is 0.4 inside.
  EXPECT_NEAR(reference::distance(m, {37, 12, 0}), -0.4, 1e-12);
  EXPECT_NEAR(reference::distance(m, {37, 12, 1.4}), 1.0, 1e-12);
}

TEST(Scale, AliasTreesCountEveryUseTowardsTheLimit) {
  // 11 levels of doubling: 2048 spheres and their transforms from a 14-line file.
  std::string s = "scene:\n  union:\n    - &a0 {sphere: {radius: 1}}\n";
  for (int i = 1; i <= 11; ++i)
    s += "    - &a" + std::to_string(i) + " {union: [*a" + std::to_string(i - 1) + ", {union: [*a" +
         std::to_string(i - 1) + "], translate: [1, 0, 0]}]}\n";
  ScratchDir dir;
  RunResult r = run_sdfc("check " + dir.write("tree.yaml", s));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("more than the limit of 4096"), std::string::npos) << r.err;
}

TEST(Scale, OnePixelPastTheLargestImageIsRefusedBeforeRendering) {
  ScratchDir dir;
  RunResult opt = run_sdfc("render examples/primitives.yaml --width 16385 -o " + dir.file("x.png"));
  EXPECT_EQ(opt.code, 2) << opt.err;
  EXPECT_NE(opt.err.find("16385"), std::string::npos) << opt.err;
  RunResult set = run_sdfc("render examples/primitives.yaml --set render.height=16385 -o " + dir.file("x.png"));
  EXPECT_EQ(set.code, 1) << set.err;
  EXPECT_NE(set.err.find("expected a whole number from 1 to 16384, got 16385"), std::string::npos) << set.err;
  EXPECT_EQ(set.err.find("device:"), std::string::npos) << "refused before the device is opened: " << set.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

}  // namespace
}  // namespace sdfc::test
