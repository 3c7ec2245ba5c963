// The work-group shape of a tile launch: CPU devices get small groups that
// always divide the launch (OpenCL 1.2 refuses a local size that does not).
#include "renderer/launch_shape.hpp"

#include <gtest/gtest.h>

namespace sdfrt {
namespace {

TEST(LaunchShape, PacketKernelsOnCpuRunOneWorkItemPerGroup) {
  for (int width : {4, 8, 16}) {
    const auto local = launch_local_size(DeviceType::Cpu, width, 320, 180);
    ASSERT_TRUE(local.has_value());
    EXPECT_EQ((*local)[0], 1u);
    EXPECT_EQ((*local)[1], 1u);
  }
}

TEST(LaunchShape, PerPixelGroupsOnCpuDivideEveryLaunch) {
  for (std::size_t gx = 1; gx <= 300; ++gx) {
    for (std::size_t gy : {1u, 5u, 6u, 37u, 208u, 256u}) {
      const auto local = launch_local_size(DeviceType::Cpu, 1, gx, gy);
      ASSERT_TRUE(local.has_value());
      EXPECT_EQ(gx % (*local)[0], 0u) << gx;
      EXPECT_EQ(gy % (*local)[1], 0u) << gy;
      EXPECT_LE((*local)[0] * (*local)[1], 64u);
    }
  }
  const auto full = launch_local_size(DeviceType::Cpu, 1, 256, 208);
  EXPECT_EQ((*full)[0], 8u);
  EXPECT_EQ((*full)[1], 8u);
}

TEST(LaunchShape, GpusKeepTheDriversChoice) {
  EXPECT_FALSE(launch_local_size(DeviceType::Gpu, 1, 256, 256).has_value());
  EXPECT_FALSE(launch_local_size(DeviceType::Other, 16, 64, 64).has_value());
}

}  // namespace
}  // namespace sdfrt
