#pragma once
// Shared helpers of the runtime tests.
#include <sdfrt/device.hpp>
#include <sdfrt/renderer.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "test_files.hpp"

namespace sdfrt::test {

using sdfc::test::read_text_file;
using sdfc::test::TempDir;

// Sets (or unsets, with nullopt) an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(std::string name, std::optional<std::string> value);
  ~ScopedEnv();
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// True when both images hold exactly the same floats (bit for bit).
bool same_bits(const FloatImage& a, const FloatImage& b);

// The default device, opened once per test process.
Device& test_device();

// Writes r = x/img_w, g = y/img_h, b = frame[0], depth = x+y.
// simd_width 1 (scalar) or 8 (float8 + vstore8).
KernelSpec gradient_spec(int simd_width);
float expected_gradient(int plane, int x, int y, int width, int height, float frame0);

}  // namespace sdfrt::test
