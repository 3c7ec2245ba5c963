#pragma once
// OpenCL device discovery and selection.
#include <sdfrt/cl_handle.hpp>
#include <sdfrt/errors.hpp>  // DeviceError, thrown by everything here

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sdfrt {

enum class DeviceType { Cpu, Gpu, Other };
std::string_view to_string(DeviceType type);

struct DeviceInfo {
  int platform_index = 0;
  int device_index = 0;   // index within its platform
  int flat_index = 0;     // index over all devices of all platforms
  std::string id;         // "P:D"
  std::string platform_name;
  std::string platform_version;
  std::string device_name;
  std::string device_version;
  DeviceType type = DeviceType::Other;
  std::string driver_version;
  std::string opencl_c_version;
  unsigned compute_units = 0;
  std::uint64_t global_mem_bytes = 0;
  std::uint64_t max_alloc_bytes = 0;
  bool fp64 = false;
};

// All devices of all platforms. Empty (not an error) when no OpenCL
// platform is installed; open_device() is the one that complains.
std::vector<DeviceInfo> list_devices();

// One opened device: context + in-order command queue with profiling on.
class Device {
 public:
  Device(DeviceInfo info, cl_device_id device, ContextHandle context, QueueHandle queue);
  Device(Device&&) noexcept = default;
  Device& operator=(Device&&) noexcept = default;

  const DeviceInfo& info() const noexcept { return info_; }
  cl_device_id id() const noexcept { return device_; }
  cl_context context() const noexcept { return context_.get(); }
  cl_command_queue queue() const noexcept { return queue_.get(); }

 private:
  DeviceInfo info_;
  cl_device_id device_ = nullptr;
  ContextHandle context_;
  QueueHandle queue_;
};

// `id` is "P:D", a flat index ("0", "1", ...) or a case-insensitive
// substring of the device name. Without it, $SDFC_DEVICE is used; without
// that, the first CPU device, else the first device.
// Throws DeviceError when nothing matches (listing the available ids).
Device open_device(std::optional<std::string> id = std::nullopt);

// One line per device for messages and `sdfc devices`:
// "0:0 (#0) pthread-... [CPU, PoCL 3.1, 2 CUs, fp64]".
std::string describe(const DeviceInfo& info);

}  // namespace sdfrt
