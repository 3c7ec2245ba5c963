#pragma once
// Internal: reading and writing cache entries. Layout of an entry:
//   "SDFCKBIN" | u64 check_hash | u64 binary size | u64 FNV-1a of binary | binary
// so a truncated or foreign file is detected and ignored.
#include "program_cache/cache_key.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace sdfrt {

// nullopt when the entry is missing, unreadable or corrupt.
std::optional<std::vector<unsigned char>> load_cached_binary(const std::filesystem::path& file,
                                                             const CacheKey& key);

// Atomic (temp file + rename). Throws IoError on failure.
void store_cached_binary(const std::filesystem::path& file, const CacheKey& key,
                         const std::vector<unsigned char>& binary);

}  // namespace sdfrt
