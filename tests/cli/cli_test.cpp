// The sdfc executable as a user meets it: exit codes, stdout for data,
// stderr for messages, --help everywhere.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_sdfc.hpp"

namespace {

using Result = sdfc::test::RunResult;
using sdfc::test::read_text;

// Runs `sdfc ARGS` from the repository root.
Result sdfc(const std::string& args) { return sdfc::test::run_sdfc(args); }

std::string write_scene(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Cli, HelpOnEveryCommand) {
  for (const char* c : {"", "check", "compile", "render", "devices"}) {
    Result r = sdfc(std::string(c) + " --help");
    EXPECT_EQ(r.code, 0) << c;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << c << ": " << r.out;
  }
}

TEST(Cli, CheckPrintsASummary) {
  Result r = sdfc("check examples/mandelbulb.yaml");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("examples/mandelbulb.yaml: ok"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mandelbulb"), std::string::npos);
  EXPECT_NE(r.out.find("lights: 3"), std::string::npos) << r.out;
}

TEST(Cli, SceneErrorsExitOneWithLocation) {
  std::string bad = write_scene("bad.yaml", "scene:\n  union:\n    - sphre: {radius: 1}\n");
  Result r = sdfc("check " + bad);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("bad.yaml:3:7: error: unknown node kind 'sphre' (did you mean 'sphere'?)"), std::string::npos)
      << r.err;
  EXPECT_EQ(sdfc("render " + bad + " -o /tmp/never.png").code, 1);
  EXPECT_EQ(sdfc("check /nonexistent.yaml").code, 1);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(sdfc("").code, 2);
  EXPECT_EQ(sdfc("frobnicate").code, 2);
  EXPECT_EQ(sdfc("render examples/mandelbulb.yaml").code, 2);  // no -o
  EXPECT_EQ(sdfc("compile examples/mandelbulb.yaml --emit asm").code, 2);
  Result r = sdfc("compile examples/mandelbulb.yaml --dump-after fold_constant");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("did you mean 'fold_constants'?"), std::string::npos) << r.err;
}

TEST(Cli, DeviceErrorsExitThree) {
  Result r = sdfc("render examples/mandelbulb.yaml -o /tmp/never.png --device 99:99");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("0:0"), std::string::npos) << "should list the ids that exist: " << r.err;
}

TEST(Cli, UnwritableOutputExitsFourAndLeavesNothing) {
  Result r = sdfc("render examples/mandelbulb.yaml --width 32 --height 18 -q -o /nonexistent-dir/m.png");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_FALSE(std::filesystem::exists("/nonexistent-dir"));
}

// A cold kernel build (no sdfc cache, an empty PoCL cache) is where the
// OpenCL compiler could talk; with -q nothing at all may reach stderr.
TEST(Cli, QuietColdBuildPrintsNothing) {
  sdfc::test::ScratchDir dir;
  Result r = sdfc::test::run_sdfc(
      "render examples/formulas/pseudo_kleinian.yaml --width 32 --height 18 -q -o " + dir.file("k.png"),
      "SDFC_KERNEL_CACHE=0 POCL_CACHE_DIR=" + dir.path() + " ");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(std::filesystem::exists(dir.file("k.png")));
}

TEST(Cli, CompileShowsEveryStage) {
  Result ast = sdfc("compile examples/mandelbulb.yaml --emit ast");
  EXPECT_EQ(ast.code, 0);
  EXPECT_NE(ast.out.find("mandelbulb: map  @13:"), std::string::npos) << ast.out;
  Result ir = sdfc("compile examples/mandelbulb.yaml --emit ir");
  EXPECT_NE(ir.out.find("= mandelbulb power=8 iterations=10 bailout=2"), std::string::npos) << ir.out;
  Result all = sdfc("compile examples/mandelbulb.yaml --emit ir --dump-after all");
  for (const char* pass : {"lower", "verify", "fold_constants", "canonicalise", "cse", "eliminate_dead", "infer_properties", "analyse", "insert_bounding_volumes", "gather_object_sets"})
    EXPECT_NE(all.out.find(std::string("// ---- IR after ") + pass + " "), std::string::npos) << pass;
  Result cl = sdfc("compile examples/mandelbulb.yaml --emit cl --simd-width 1");
  EXPECT_NE(cl.out.find("__kernel void sdfc_render("), std::string::npos);
  EXPECT_NE(cl.out.find("de_mandelbulb_int(p"), std::string::npos);
}

TEST(Cli, CompileWritesAFile) {
  std::string out = ::testing::TempDir() + "/k.cl";
  Result r = sdfc("compile examples/primitives.yaml -o " + out);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(read_text(out).find("sd_torus"), std::string::npos);
}

TEST(Cli, SetOverridesAnyValue) {
  Result r = sdfc("compile examples/mandelbulb.yaml --emit ir --set scene.union.0.mandelbulb.power=7 --set render.width=640");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("mandelbulb power=7"), std::string::npos);
  EXPECT_NE(r.out.find("render 640x720"), std::string::npos);
  Result bad = sdfc("check examples/mandelbulb.yaml --set render.width=wide");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("--set render.width:1:14: error"), std::string::npos) << bad.err;
}

TEST(Cli, DevicesListsPocl) {
  Result r = sdfc("devices");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("0:0"), std::string::npos) << r.out;
}

}  // namespace

namespace {

TEST(Cli, AuditRunsOnAScene) {
  Result r = sdfc("audit examples/primitives.yaml --rays 16 --lines 8");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("node"), std::string::npos);
  EXPECT_NE(r.out.find("torus"), std::string::npos) << r.out;
  Result j = sdfc("audit examples/primitives.yaml --rays 16 --lines 8 --json");
  EXPECT_EQ(j.out.rfind("{\"nodes\": [", 0), 0u) << j.out;
  std::string steep = write_scene("steep.yaml",
                                  "render: {lipschitz_correction: false}\n"
                                  "scene: {box: {size: [1.0, 0.3, 2.0]}, twist: {axis: z, rate: 3}}\n");
  Result s = sdfc("audit " + steep + " --strict");
  EXPECT_EQ(s.code, 1) << s.out << s.err;
  EXPECT_NE(s.out.find("WARNING"), std::string::npos) << s.out;
}

}  // namespace
