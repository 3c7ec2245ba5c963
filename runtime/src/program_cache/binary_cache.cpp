#include "program_cache/binary_cache.hpp"

#include <sdfrt/program.hpp>

#include "image_io/atomic_file.hpp"
#include "program_cache/fnv1a.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace sdfrt {
namespace {

constexpr std::array<char, 8> kMagic = {'S', 'D', 'F', 'C', 'K', 'B', 'I', 'N'};
constexpr std::size_t kHeaderSize = kMagic.size() + 3 * sizeof(std::uint64_t);
// Far above any real program binary; guards against allocating garbage sizes.
constexpr std::uint64_t kMaxBinarySize = 1ull << 30;

void put_u64(std::vector<unsigned char>& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<unsigned char>(value >> (8 * i)));
}

std::uint64_t get_u64(const unsigned char* p) {
  std::uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  return value;
}

std::uint64_t hash_binary(const std::vector<unsigned char>& binary) {
  Fnv1a64 h;
  h.bytes(binary.data(), binary.size());
  return h.digest();
}

const char* env(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? value : nullptr;
}

}  // namespace

std::optional<std::filesystem::path> kernel_cache_dir() {
  if (const char* dir = env("SDFC_CACHE_DIR")) return std::filesystem::path(dir);
  if (const char* xdg = env("XDG_CACHE_HOME")) return std::filesystem::path(xdg) / "sdfc" / "kernels";
  if (const char* home = env("HOME")) return std::filesystem::path(home) / ".cache" / "sdfc" / "kernels";
  return std::nullopt;
}

bool kernel_cache_enabled() {
  const char* value = env("SDFC_KERNEL_CACHE");
  if (!value) return true;
  std::string v(value);
  std::transform(v.begin(), v.end(), v.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return !(v == "0" || v == "off" || v == "false" || v == "no");
}

std::optional<std::vector<unsigned char>> load_cached_binary(const std::filesystem::path& file,
                                                             const CacheKey& key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::array<unsigned char, kHeaderSize> header{};
  if (!in.read(reinterpret_cast<char*>(header.data()), header.size())) return std::nullopt;
  if (std::memcmp(header.data(), kMagic.data(), kMagic.size()) != 0) return std::nullopt;
  const unsigned char* fields = header.data() + kMagic.size();
  if (get_u64(fields) != key.check_hash) return std::nullopt;
  const std::uint64_t size = get_u64(fields + 8);
  if (size == 0 || size > kMaxBinarySize) return std::nullopt;
  std::vector<unsigned char> binary(size);
  if (!in.read(reinterpret_cast<char*>(binary.data()), static_cast<std::streamsize>(size))) {
    return std::nullopt;
  }
  if (in.peek() != std::ifstream::traits_type::eof()) return std::nullopt;  // trailing junk
  if (hash_binary(binary) != get_u64(fields + 16)) return std::nullopt;
  return binary;
}

void store_cached_binary(const std::filesystem::path& file, const CacheKey& key,
                         const std::vector<unsigned char>& binary) {
  std::vector<unsigned char> header(kMagic.begin(), kMagic.end());
  put_u64(header, key.check_hash);
  put_u64(header, binary.size());
  put_u64(header, hash_binary(binary));

  AtomicFile out(file.string());
  out.write(header.data(), header.size());
  out.write(binary.data(), binary.size());
  out.commit();
}

}  // namespace sdfrt
