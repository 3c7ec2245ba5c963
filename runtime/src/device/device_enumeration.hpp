#pragma once
// Internal: devices paired with their cl_device_id, so open_device can use
// the same enumeration that list_devices shows.
#include <sdfrt/device.hpp>

#include <vector>

namespace sdfrt {

struct EnumeratedDevice {
  DeviceInfo info;
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
};

std::vector<EnumeratedDevice> enumerate_devices();

}  // namespace sdfrt
