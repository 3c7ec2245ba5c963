// sdfc devices: the OpenCL platforms and devices, with the ids --device takes.
#include <fmt/format.h>

#include <sdfrt/device.hpp>
#include <sdfrt/errors.hpp>

#include "commands.hpp"

namespace sdfc::cli {

Action add_devices(CLI::App& app) {
  app.add_subcommand("devices", "List OpenCL platforms and devices with their ids");
  return [] {
    auto devices = sdfrt::list_devices();
    if (devices.empty()) throw sdfrt::DeviceError("no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)");
    fmt::print("{:<5} {:<4} {:<6} {:<40} {}\n", "id", "#", "type", "device", "platform / driver");
    for (const auto& d : devices)
      fmt::print("{:<5} {:<4} {:<6} {:<40} {} / {}, {} compute units, {} MiB{}\n", d.id, d.flat_index,
                 sdfrt::to_string(d.type), d.device_name.substr(0, 40), d.platform_name, d.driver_version,
                 d.compute_units, d.global_mem_bytes >> 20, d.fp64 ? ", fp64" : "");
    return kOk;
  };
}

}  // namespace sdfc::cli
