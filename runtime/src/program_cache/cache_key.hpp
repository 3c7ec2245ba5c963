#pragma once
// Internal: what identifies a cached program binary.
#include <sdfrt/device.hpp>

#include <cstdint>
#include <string>

namespace sdfrt {

struct CacheKey {
  std::uint64_t name_hash = 0;   // names the file
  std::uint64_t check_hash = 0;  // independent second hash, stored inside the file
  std::string file_name() const;  // "<16 hex digits>.bin"
};

CacheKey make_cache_key(const DeviceInfo& device, const std::string& source,
                        const std::string& options);

}  // namespace sdfrt
