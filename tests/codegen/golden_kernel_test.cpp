// Golden kernel frames: the emitted OpenCL for two examples without the
// stdlib's text and without the scene functions (those have their own
// goldens in golden_parts_test.cpp), so what is left is the assembly: the
// header, materials, lighting, the march/shading segment and the entry
// points. An stdlib edit changes none of these files. Regenerate with
//   SDFC_UPDATE_GOLDEN=1 ctest -R Golden
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
  std::string frame = test::kernel_sections(kernel, {"// ---- stdlib"}, false);
  frame = test::kernel_sections(frame, test::scene_section_titles(), false);
  ASSERT_NE(frame.find("__kernel"), std::string::npos) << "no entry point left";
  test::expect_golden(frame, "kernel/" + golden_name);
}

TEST(GoldenKernel, Mandelbulb) { check_golden("mandelbulb.yaml", 1, "mandelbulb.w1.cl"); }
TEST(GoldenKernel, Primitives) { check_golden("primitives.yaml", 1, "primitives.w1.cl"); }
TEST(GoldenKernel, MandelbulbPacket) { check_golden("mandelbulb.yaml", 8, "mandelbulb.w8.cl"); }

}  // namespace
}  // namespace sdfc
