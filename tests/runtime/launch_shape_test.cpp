// The work-group shape of a tile launch: one fixed, always-dividing size on
// CPU devices; the driver's choice elsewhere.
#include "renderer/launch_shape.hpp"

#include <sdfrt/errors.hpp>
#include <sdfrt/renderer.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

namespace sdfrt {
namespace {

TEST(LaunchShape, CpuDevicesRunOneWorkItemPerGroup) {
  const auto local = launch_local_size(DeviceType::Cpu);
  ASSERT_TRUE(local.has_value());
  EXPECT_EQ((*local)[0], 1u);
  EXPECT_EQ((*local)[1], 1u);
}

TEST(LaunchShape, GpusKeepTheDriversChoice) {
  EXPECT_FALSE(launch_local_size(DeviceType::Gpu).has_value());
  EXPECT_FALSE(launch_local_size(DeviceType::Other).has_value());
}

// Odd image and tile sizes give launches of every shape; each must be
// accepted by the driver (a local size that does not divide is an error).
TEST(LaunchShape, EveryTileShapeLaunches) {
  for (int simd : {1, 8}) {
    Renderer renderer(test::test_device(), test::gradient_spec(simd));
    for (int tile : {3, 7, 16, 29}) {
      RenderOptions options;
      options.tile_width = options.tile_height = tile;
      EXPECT_NO_THROW(renderer.render({0.5f}, 61, 23, options)) << simd << " " << tile;
    }
  }
}

}  // namespace
}  // namespace sdfrt
