// Golden kernels: the emitted OpenCL for two examples, diffed against
// tests/golden/. After an intended change, regenerate them with
//   SDFC_UPDATE_GOLDEN=1 ctest -R Golden
// and review the diff like any other change.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "sdfc/compile.hpp"

namespace sdfc {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool ea = !std::getline(sa, la), eb = !std::getline(sb, lb);
    if (ea && eb) return "";
    if (ea || eb || la != lb)
      return "line " + std::to_string(line) + ":\n  golden: " + (ea ? "<end>" : la) + "\n  actual: " + (eb ? "<end>" : lb);
  }
}

void check_golden(const std::string& example, int simd_width, const std::string& golden_name) {
  std::string src = std::string(SDFC_SOURCE_DIR) + "/examples/" + example;
  // The scene name in the kernel's comments is the path relative to the repo.
  ir::Module m = build_module(load_scene_source(src, {}), "examples/" + example);
  std::string kernel = codegen::emit_opencl(m, {simd_width, false}).source;
  std::string golden_path = std::string(SDFC_SOURCE_DIR) + "/tests/golden/" + golden_name;
  if (const char* u = std::getenv("SDFC_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::ofstream(golden_path) << kernel;
    GTEST_SKIP() << "updated " << golden_path;
  }
  std::string golden = read_file(golden_path);
  ASSERT_FALSE(golden.empty()) << "missing " << golden_path << " (run with SDFC_UPDATE_GOLDEN=1)";
  EXPECT_TRUE(kernel == golden) << golden_name << " differs at " << first_difference(golden, kernel);
}

TEST(GoldenKernel, Mandelbulb) { check_golden("mandelbulb.yaml", 1, "mandelbulb.w1.cl"); }
TEST(GoldenKernel, Primitives) { check_golden("primitives.yaml", 1, "primitives.w1.cl"); }
TEST(GoldenKernel, MandelbulbPacket) { check_golden("mandelbulb.yaml", 8, "mandelbulb.w8.cl"); }

}  // namespace
}  // namespace sdfc
