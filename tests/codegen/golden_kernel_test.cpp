// Golden kernels: the emitted OpenCL for two examples, diffed against
// tests/golden/ (golden_file.hpp says how to regenerate them).
#include <gtest/gtest.h>

#include "golden_file.hpp"
#include "sdfc/compile.hpp"

namespace sdfc {
namespace {

void check_golden(const std::string& example, int simd_width, const std::string& golden_name) {
  std::string src = std::string(SDFC_SOURCE_DIR) + "/examples/" + example;
  // The scene name in the kernel's comments is the path relative to the repo.
  ir::Module m = build_module(load_scene_source(src, {}), "examples/" + example);
  std::string kernel = codegen::emit_opencl(m, {simd_width, false}).source;
  test::expect_golden(kernel, golden_name);
}

TEST(GoldenKernel, Mandelbulb) { check_golden("mandelbulb.yaml", 1, "mandelbulb.w1.cl"); }
TEST(GoldenKernel, Primitives) { check_golden("primitives.yaml", 1, "primitives.w1.cl"); }
TEST(GoldenKernel, MandelbulbPacket) { check_golden("mandelbulb.yaml", 8, "mandelbulb.w8.cl"); }

}  // namespace
}  // namespace sdfc
