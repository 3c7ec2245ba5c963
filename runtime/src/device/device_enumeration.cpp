#include "device/device_enumeration.hpp"

#include "device/cl_check.hpp"

#include <CL/cl_ext.h>  // CL_PLATFORM_NOT_FOUND_KHR

#include <cstdlib>
#include <mutex>
#include <string>

namespace sdfrt {
namespace {

std::string platform_string(cl_platform_id platform, cl_platform_info param) {
  std::size_t size = 0;
  check_cl(clGetPlatformInfo(platform, param, 0, nullptr, &size), "clGetPlatformInfo");
  std::string value(size, '\0');
  check_cl(clGetPlatformInfo(platform, param, size, value.data(), nullptr), "clGetPlatformInfo");
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

std::string device_string(cl_device_id device, cl_device_info param) {
  std::size_t size = 0;
  check_cl(clGetDeviceInfo(device, param, 0, nullptr, &size), "clGetDeviceInfo");
  std::string value(size, '\0');
  check_cl(clGetDeviceInfo(device, param, size, value.data(), nullptr), "clGetDeviceInfo");
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

template <typename T>
T device_value(cl_device_id device, cl_device_info param) {
  T value{};
  check_cl(clGetDeviceInfo(device, param, sizeof(T), &value, nullptr), "clGetDeviceInfo");
  return value;
}

DeviceType classify(cl_device_type type) {
  if (type & CL_DEVICE_TYPE_GPU) return DeviceType::Gpu;
  if (type & CL_DEVICE_TYPE_CPU) return DeviceType::Cpu;
  return DeviceType::Other;
}

// PoCL compiles a kernel's work-group function once more for each new launch
// shape unless told not to. Our CPU launches are one packet per work-group,
// so the specialised copy runs no faster (bench scene: the same frame time),
// while the generic copy is the one PoCL already compiles for the program's
// binary (our kernel cache): without this, a first render compiles the
// kernel's machine code twice (about 0.5 s more at start-up). A value the
// user set wins. Set before the first OpenCL call, once.
void prefer_generic_work_groups() {
  static std::once_flag once;
  std::call_once(once, [] { ::setenv("POCL_WORK_GROUP_SPECIALIZATION", "0", /*overwrite=*/0); });
}

std::vector<cl_platform_id> platforms() {
  prefer_generic_work_groups();
  cl_uint count = 0;
  cl_int status = clGetPlatformIDs(0, nullptr, &count);
  // The ICD loader reports "no platform" as an error; for us it is just none.
  if (status == CL_PLATFORM_NOT_FOUND_KHR || count == 0) return {};
  check_cl(status, "clGetPlatformIDs");
  std::vector<cl_platform_id> ids(count);
  check_cl(clGetPlatformIDs(count, ids.data(), nullptr), "clGetPlatformIDs");
  return ids;
}

std::vector<cl_device_id> devices_of(cl_platform_id platform) {
  cl_uint count = 0;
  cl_int status = clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, 0, nullptr, &count);
  if (status == CL_DEVICE_NOT_FOUND || count == 0) return {};
  check_cl(status, "clGetDeviceIDs");
  std::vector<cl_device_id> ids(count);
  check_cl(clGetDeviceIDs(platform, CL_DEVICE_TYPE_ALL, count, ids.data(), nullptr),
           "clGetDeviceIDs");
  return ids;
}

}  // namespace

std::vector<EnumeratedDevice> enumerate_devices() {
  std::vector<EnumeratedDevice> result;
  const auto platform_ids = platforms();
  for (std::size_t p = 0; p < platform_ids.size(); ++p) {
    const auto device_ids = devices_of(platform_ids[p]);
    for (std::size_t d = 0; d < device_ids.size(); ++d) {
      cl_device_id dev = device_ids[d];
      DeviceInfo info;
      info.platform_index = static_cast<int>(p);
      info.device_index = static_cast<int>(d);
      info.flat_index = static_cast<int>(result.size());
      info.id = std::to_string(p) + ":" + std::to_string(d);
      info.platform_name = platform_string(platform_ids[p], CL_PLATFORM_NAME);
      info.platform_version = platform_string(platform_ids[p], CL_PLATFORM_VERSION);
      info.device_name = device_string(dev, CL_DEVICE_NAME);
      info.device_version = device_string(dev, CL_DEVICE_VERSION);
      info.type = classify(device_value<cl_device_type>(dev, CL_DEVICE_TYPE));
      info.driver_version = device_string(dev, CL_DRIVER_VERSION);
      info.opencl_c_version = device_string(dev, CL_DEVICE_OPENCL_C_VERSION);
      info.compute_units = device_value<cl_uint>(dev, CL_DEVICE_MAX_COMPUTE_UNITS);
      info.global_mem_bytes = device_value<cl_ulong>(dev, CL_DEVICE_GLOBAL_MEM_SIZE);
      info.max_alloc_bytes = device_value<cl_ulong>(dev, CL_DEVICE_MAX_MEM_ALLOC_SIZE);
      info.fp64 = device_value<cl_device_fp_config>(dev, CL_DEVICE_DOUBLE_FP_CONFIG) != 0;
      result.push_back({std::move(info), platform_ids[p], dev});
    }
  }
  return result;
}

std::vector<DeviceInfo> list_devices() {
  std::vector<DeviceInfo> infos;
  for (auto& entry : enumerate_devices()) infos.push_back(std::move(entry.info));
  return infos;
}

}  // namespace sdfrt
