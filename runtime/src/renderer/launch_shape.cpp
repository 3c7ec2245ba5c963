#include "renderer/launch_shape.hpp"

namespace sdfrt {

std::optional<std::array<std::size_t, 2>> launch_local_size(DeviceType type) {
  if (type != DeviceType::Cpu) return std::nullopt;
  return std::array<std::size_t, 2>{1, 1};
}

}  // namespace sdfrt
