// The kernel ABI (sdfc/codegen/kernel_abi.hpp): the planes a kernel writes
// are in its order, and the frame block carries each value where the
// kernel reads it.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "scene_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

codegen::EmittedKernel kernel_of(const std::string& yaml, bool aovs) {
  codegen::EmitOptions opt;
  opt.simd_width = 8;
  opt.aovs = aovs;
  return codegen::emit_opencl(passes::run_pipeline(test::lower_text(yaml)), opt);
}

TEST(KernelAbi, PlanesAreInTheAbiOrder) {
  auto plain = kernel_of("scene: {sphere: {radius: 1}}\n", false);
  ASSERT_EQ(plain.planes.size(), abi::kImagePlanes.size());
  auto full = kernel_of("scene: {sphere: {radius: 1}}\n", true);
  ASSERT_EQ(full.planes.size(), abi::kImagePlanes.size() + abi::kAovPlanes.size());
  for (size_t i = 0; i < full.planes.size(); ++i) {
    EXPECT_EQ(abi::plane_index(full.planes[i]), int(i)) << full.planes[i];
    // The kernel stores plane i at i planes past the packet's origin.
    std::string at = i == 0 ? "o, out_stride" : i == 1 ? "o + plane, out_stride" : fmt::format("o + {} * plane, out_stride", i);
    EXPECT_NE(full.source.find(at), std::string::npos) << full.planes[i];
  }
  EXPECT_EQ(abi::plane_index("no_such_plane"), -1);
  EXPECT_EQ(full.frame_floats, abi::kFrameFloats);
}

TEST(KernelAbi, TheFrameBlockHoldsEachValueWhereTheKernelReadsIt) {
  ir::Module m = passes::run_pipeline(test::lower_text(
      "render: {samples: 4}\ncamera: {position: [0, -5, 0], target: [0, 0, 0], aperture: 0.1, focus_distance: 4}\n"
      "scene: {sphere: {radius: \"1 + 0.1*sin(time)\"}}\n"));
  std::vector<float> f = codegen::frame_params(m.plan, 64, 32, 1.5);
  ASSERT_EQ(f.size(), size_t(abi::kFrameFloats));
  EXPECT_FLOAT_EQ(f[abi::kTime], 1.5f);
  EXPECT_FLOAT_EQ(f[abi::kFirstSample], 0.0f);
  EXPECT_FLOAT_EQ(f[abi::kSampleCount], 4.0f);
  EXPECT_FLOAT_EQ(f[abi::kFocus], 4.0f);
  EXPECT_FLOAT_EQ(f[abi::kEye + 1] + f[abi::kEye + abi::kLowPart + 1], -5.0f);
  EXPECT_FLOAT_EQ(f[abi::kForward + 1], 1.0f);  // towards the target
  std::string src = codegen::emit_opencl(m, {8, false}).source;
  for (int at : {abi::kPixelAngle, abi::kTime, abi::kFirstSample, abi::kSampleCount, abi::kFocus}) {
    bool reads = src.find(fmt::format("(scalar)frame[{}]", at)) != std::string::npos ||
                 src.find(fmt::format("(int)frame[{}]", at)) != std::string::npos;
    EXPECT_TRUE(reads) << "the kernel does not read frame[" << at << "]";
  }
}

}  // namespace
}  // namespace sdfc
