#pragma once
// Internal: which device an id string means (pure, no OpenCL calls).
#include <sdfrt/device.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sdfrt {

// Index into `devices`. `origin` names where the id came from, for messages
// ("--device", "SDFC_DEVICE"). Throws DeviceError when nothing matches.
std::size_t select_device(const std::vector<DeviceInfo>& devices,
                          const std::optional<std::string>& id, const std::string& origin);

}  // namespace sdfrt
