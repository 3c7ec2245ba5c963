#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace sdfrt::test {

ScopedEnv::ScopedEnv(std::string name, std::optional<std::string> value) : name_(std::move(name)) {
  if (const char* old = std::getenv(name_.c_str())) old_ = old;
  if (value) {
    ::setenv(name_.c_str(), value->c_str(), 1);
  } else {
    ::unsetenv(name_.c_str());
  }
}

ScopedEnv::~ScopedEnv() {
  if (old_) {
    ::setenv(name_.c_str(), old_->c_str(), 1);
  } else {
    ::unsetenv(name_.c_str());
  }
}

bool same_bits(const FloatImage& a, const FloatImage& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

Device& test_device() {
  static Device device = open_device();
  return device;
}

namespace {

constexpr const char* kSignature = R"(
__kernel void sdfc_render(__global float* out, __global const float* frame,
                          const int img_w, const int img_h,
                          const int tile_x0, const int tile_y0,
                          const int tile_w, const int tile_h,
                          const int out_stride)
)";

constexpr const char* kScalarBody = R"({
  const int lx = get_global_id(0);
  const int ly = get_global_id(1);
  const int x = tile_x0 + lx;
  const int y = tile_y0 + ly;
  const int plane = out_stride * tile_h;
  const int i = ly * out_stride + lx;
  out[i] = (float)x / (float)img_w;
  out[plane + i] = (float)y / (float)img_h;
  out[2 * plane + i] = frame[0];
  out[3 * plane + i] = (float)(x + y);
}
)";

// Lanes past tile_w land in the row padding, which the host must ignore.
constexpr const char* kSimd8Body = R"({
  const int lx = get_global_id(0) * 8;
  const int ly = get_global_id(1);
  const float8 x = (float)(tile_x0 + lx) + (float8)(0, 1, 2, 3, 4, 5, 6, 7);
  const float y = (float)(tile_y0 + ly);
  const int plane = out_stride * tile_h;
  __global float* p = out + ly * out_stride + lx;
  vstore8(x / (float)img_w, 0, p);
  vstore8((float8)(y / (float)img_h), 0, p + plane);
  vstore8((float8)(frame[0]), 0, p + 2 * plane);
  vstore8(x + y, 0, p + 3 * plane);
}
)";

// Keeps every test process's kernel cache out of the user's ~/.cache.
class PrivateCacheEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    dir_.emplace();
    env_.emplace("SDFC_CACHE_DIR", dir_->path().string());
  }
  void TearDown() override {
    env_.reset();
    dir_.reset();
  }

 private:
  std::optional<TempDir> dir_;
  std::optional<ScopedEnv> env_;
};

[[maybe_unused]] ::testing::Environment* const kPrivateCache =
    ::testing::AddGlobalTestEnvironment(new PrivateCacheEnvironment);

}  // namespace

KernelSpec gradient_spec(int simd_width) {
  if (simd_width != 1 && simd_width != 8) throw std::invalid_argument("simd_width 1 or 8");
  KernelSpec spec;
  spec.source = std::string(kSignature) + (simd_width == 1 ? kScalarBody : kSimd8Body);
  spec.simd_width = simd_width;
  spec.planes = {"r", "g", "b", "depth"};
  return spec;
}

float expected_gradient(int plane, int x, int y, int width, int height, float frame0) {
  switch (plane) {
    case 0: return static_cast<float>(x) / static_cast<float>(width);
    case 1: return static_cast<float>(y) / static_cast<float>(height);
    case 2: return frame0;
    default: return static_cast<float>(x + y);
  }
}

}  // namespace sdfrt::test
