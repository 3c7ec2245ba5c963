#pragma once
// Internal: 64-bit FNV-1a. Not cryptographic; only used to name and check
// cache entries, where an accidental collision is the only concern.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace sdfrt {

class Fnv1a64 {
 public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ull;
  static constexpr std::uint64_t kPrime = 0x100000001b3ull;

  explicit Fnv1a64(std::uint64_t basis = kOffsetBasis) : state_(basis) {}

  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      state_ ^= p[i];
      state_ *= kPrime;
    }
  }
  void u64(std::uint64_t value) {
    for (int i = 0; i < 8; ++i) {
      const unsigned char byte = static_cast<unsigned char>(value >> (8 * i));
      bytes(&byte, 1);
    }
  }
  // Length-prefixed so ("ab","c") and ("a","bc") hash differently.
  void field(std::string_view text) {
    u64(text.size());
    bytes(text.data(), text.size());
  }
  std::uint64_t digest() const { return state_; }

 private:
  std::uint64_t state_;
};

}  // namespace sdfrt
