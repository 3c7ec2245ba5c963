#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>

namespace sdfrt {
namespace {

using test::ScopedEnv;

TEST(Devices, ListsAtLeastOneDeviceWithInfo) {
  const auto devices = list_devices();
  ASSERT_FALSE(devices.empty());
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const auto& d = devices[i];
    EXPECT_EQ(d.flat_index, static_cast<int>(i));
    EXPECT_EQ(d.id, std::to_string(d.platform_index) + ":" + std::to_string(d.device_index));
    EXPECT_FALSE(d.device_name.empty());
    EXPECT_FALSE(d.platform_name.empty());
    EXPECT_NE(d.opencl_c_version.find("OpenCL C"), std::string::npos);
    EXPECT_GT(d.compute_units, 0u);
    EXPECT_GT(d.global_mem_bytes, 0u);
    EXPECT_GT(d.max_alloc_bytes, 0u);
    EXPECT_NE(describe(d).find(d.id), std::string::npos);
  }
}

TEST(Devices, DefaultPrefersCpu) {
  ScopedEnv no_env("SDFC_DEVICE", std::nullopt);
  const auto devices = list_devices();
  const bool has_cpu = std::any_of(devices.begin(), devices.end(),
                                   [](const DeviceInfo& d) { return d.type == DeviceType::Cpu; });
  Device device = open_device();
  if (has_cpu) {
    EXPECT_EQ(device.info().type, DeviceType::Cpu);
  }
  EXPECT_NE(device.context(), nullptr);
  EXPECT_NE(device.queue(), nullptr);
}

TEST(Devices, OpensByPlatformDeviceIdFlatIndexAndNameSubstring) {
  ScopedEnv no_env("SDFC_DEVICE", std::nullopt);
  const auto first = list_devices().front();
  EXPECT_EQ(open_device(first.id).info().id, first.id);
  EXPECT_EQ(open_device("0").info().id, first.id);

  std::string shouting = first.device_name.substr(0, std::min<std::size_t>(first.device_name.size(), 7));
  std::transform(shouting.begin(), shouting.end(), shouting.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  EXPECT_EQ(open_device(shouting).info().device_name, first.device_name);
}

TEST(Devices, EnvironmentVariableSelectsAndExplicitIdWins) {
  const auto first = list_devices().front();
  {
    ScopedEnv env("SDFC_DEVICE", first.id);
    EXPECT_EQ(open_device().info().id, first.id);
  }
  {
    ScopedEnv env("SDFC_DEVICE", "no-such-device-from-env");
    try {
      open_device();
      FAIL() << "expected DeviceError";
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("SDFC_DEVICE"), std::string::npos) << e.what();
    }
    EXPECT_EQ(open_device(first.id).info().id, first.id);
  }
}

TEST(Devices, UnknownIdThrowsDeviceErrorListingIds) {
  ScopedEnv no_env("SDFC_DEVICE", std::nullopt);
  for (const std::string bad : {"no-such-gpu", "7:3", "999"}) {
    try {
      open_device(bad);
      FAIL() << "expected DeviceError for " << bad;
    } catch (const DeviceError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("'" + bad + "'"), std::string::npos) << message;
      for (const auto& d : list_devices()) {
        EXPECT_NE(message.find(d.id), std::string::npos) << message;
      }
    }
  }
}

TEST(Devices, ErrorCodesHaveNames) {
  EXPECT_EQ(cl_error_name(-5), "CL_OUT_OF_RESOURCES");
  EXPECT_EQ(cl_error_name(-11), "CL_BUILD_PROGRAM_FAILURE");
  EXPECT_EQ(cl_error_name(-1001), "CL_PLATFORM_NOT_FOUND_KHR");
  EXPECT_EQ(cl_error_name(-4242), "unknown OpenCL error -4242");
}

}  // namespace
}  // namespace sdfrt
