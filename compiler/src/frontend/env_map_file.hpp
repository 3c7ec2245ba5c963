#pragma once
// Reading an equirectangular environment map (.exr with OpenEXR, .hdr with
// stb_image) and building the tables its importance sampling draws from.
#include <stdexcept>
#include <string>
#include <vector>

namespace sdfc::frontend {

// Caps on a map: its sides, its pixels and its file's size, so a scene
// cannot make the host or the kernel buffer arbitrarily large.
inline constexpr int kEnvMaxWidth = 8192;
inline constexpr int kEnvMaxHeight = 4096;
inline constexpr long long kEnvMaxPixels = 4096LL * 2048;
inline constexpr long long kEnvMaxFileBytes = 512LL << 20;

struct EnvPixels {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width x height x 3, top row first
};

// Why a map cannot be used, in words for the scene's author.
struct EnvMapError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws EnvMapError for a missing, unreadable, broken, too large or
// unsupported file. Values that are not finite or negative become 0.
EnvPixels read_env_pixels(const std::string& path);

// The kernel buffer (ir::EnvironmentMap::data's layout): the pixels times
// `intensity`, the marginal CDF over rows and each row's CDF over its
// pixels, with weights luminance x sin(theta) (importance) or sin(theta)
// (uniform over the sphere). An all-black map is sampled uniformly.
std::vector<float> env_tables(const EnvPixels& px, double intensity, bool importance);

}  // namespace sdfc::frontend
