#include "program_cache/cache_key.hpp"

#include "program_cache/fnv1a.hpp"

#include <fmt/format.h>

namespace sdfrt {
namespace {

// Bump when the cache file layout or the key material changes.
constexpr std::string_view kKeyVersion = "sdfrt-kernel-cache-v1";

std::uint64_t hash_key(std::uint64_t basis, const DeviceInfo& device, const std::string& source,
                       const std::string& options) {
  Fnv1a64 h(basis);
  h.field(kKeyVersion);
  h.field(source);
  h.field(device.device_name);
  h.field(device.device_version);
  h.field(device.driver_version);
  h.field(device.platform_name);
  h.field(device.platform_version);
  h.field(options);
  return h.digest();
}

}  // namespace

std::string CacheKey::file_name() const { return fmt::format("{:016x}.bin", name_hash); }

CacheKey make_cache_key(const DeviceInfo& device, const std::string& source,
                        const std::string& options) {
  // A different basis gives a second, practically independent hash.
  constexpr std::uint64_t kCheckBasis = 0x84222325cbf29ce4ull;
  return {hash_key(Fnv1a64::kOffsetBasis, device, source, options),
          hash_key(kCheckBasis, device, source, options)};
}

}  // namespace sdfrt
