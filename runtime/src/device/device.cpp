#include <sdfrt/device.hpp>

#include "device/cl_check.hpp"
#include "device/device_enumeration.hpp"
#include "device/device_selection.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace sdfrt {

std::string_view to_string(DeviceType type) {
  switch (type) {
    case DeviceType::Cpu: return "CPU";
    case DeviceType::Gpu: return "GPU";
    case DeviceType::Other: return "other";
  }
  return "other";
}

std::string describe(const DeviceInfo& info) {
  return fmt::format("{} (#{}) {} [{}, {} / {}, {} CUs, {} MiB{}]", info.id, info.flat_index,
                     info.device_name, to_string(info.type), info.platform_name,
                     info.driver_version, info.compute_units, info.global_mem_bytes >> 20,
                     info.fp64 ? ", fp64" : "");
}

Device::Device(DeviceInfo info, cl_device_id device, ContextHandle context, QueueHandle queue)
    : info_(std::move(info)), device_(device), context_(std::move(context)),
      queue_(std::move(queue)) {}

Device open_device(std::optional<std::string> id) {
  std::string origin = "the device argument";
  if (!id) {
    if (const char* env = std::getenv("SDFC_DEVICE"); env && *env) {
      id = env;
      origin = "SDFC_DEVICE";
    }
  }

  auto devices = enumerate_devices();
  if (devices.empty()) {
    throw DeviceError(
        "no OpenCL platform/device found (is an OpenCL driver such as pocl-opencl-icd "
        "installed, and is /etc/OpenCL/vendors populated?)");
  }
  std::vector<DeviceInfo> infos;
  for (const auto& d : devices) infos.push_back(d.info);
  const auto& chosen = devices[select_device(infos, id, origin)];

  const cl_context_properties props[] = {
      CL_CONTEXT_PLATFORM, reinterpret_cast<cl_context_properties>(chosen.platform), 0};
  cl_int status = CL_SUCCESS;
  ContextHandle context(clCreateContext(props, 1, &chosen.device, nullptr, nullptr, &status));
  check_cl(status, fmt::format("clCreateContext for device {} ({})", chosen.info.id,
                               chosen.info.device_name));
  // Profiling is always on: the renderer reports kernel time from events.
  QueueHandle queue(clCreateCommandQueue(context.get(), chosen.device,
                                         CL_QUEUE_PROFILING_ENABLE, &status));
  check_cl(status, fmt::format("clCreateCommandQueue for device {}", chosen.info.id));
  return Device(chosen.info, chosen.device, std::move(context), std::move(queue));
}

}  // namespace sdfrt
