#include "device/device_selection.hpp"

#include <sdfrt/errors.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <regex>

namespace sdfrt {
namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool all_digits(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(),
                                      [](unsigned char c) { return std::isdigit(c); });
}

std::string available_list(const std::vector<DeviceInfo>& devices) {
  std::string list;
  for (const auto& info : devices) list += "\n  " + describe(info);
  return list;
}

}  // namespace

std::size_t select_device(const std::vector<DeviceInfo>& devices,
                          const std::optional<std::string>& id, const std::string& origin) {
  if (devices.empty()) {
    throw DeviceError(
        "no OpenCL device found: no platform reported any device "
        "(is an OpenCL driver such as pocl-opencl-icd installed?)");
  }
  if (!id || id->empty()) {
    auto cpu = std::find_if(devices.begin(), devices.end(),
                            [](const DeviceInfo& d) { return d.type == DeviceType::Cpu; });
    return cpu != devices.end() ? static_cast<std::size_t>(cpu - devices.begin()) : 0;
  }

  static const std::regex platform_device(R"((\d+):(\d+))");
  for (std::size_t i = 0; i < devices.size(); ++i) {
    if (devices[i].id == *id) return i;
  }
  if (!std::regex_match(*id, platform_device)) {
    if (all_digits(*id)) {
      // Too many digits for an index is simply "no such device".
      if (id->size() < 9) {
        std::size_t index = std::stoul(*id);
        if (index < devices.size()) return index;
      }
    } else {
      const std::string needle = lowercase(*id);
      for (std::size_t i = 0; i < devices.size(); ++i) {
        if (lowercase(devices[i].device_name).find(needle) != std::string::npos) return i;
      }
    }
  }
  throw DeviceError(fmt::format(
      "unknown OpenCL device '{}' (from {}); use \"P:D\", a flat index or part of the "
      "device name. Available devices:{}",
      *id, origin, available_list(devices)));
}

}  // namespace sdfrt
