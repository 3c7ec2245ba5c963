#include "video/ffmpeg_api.hpp"

#include <array>
#include <string>

#include "loading/dynamic_library.hpp"

namespace sdfrt {
namespace {

#define SDFRT_STR2(x) #x
#define SDFRT_STR(x) SDFRT_STR2(x)
// The sonames of the FFmpeg these headers belong to.
constexpr std::array<const char*, 4> kLibraries = {
    "libavutil.so." SDFRT_STR(LIBAVUTIL_VERSION_MAJOR), "libswscale.so." SDFRT_STR(LIBSWSCALE_VERSION_MAJOR),
    "libavcodec.so." SDFRT_STR(LIBAVCODEC_VERSION_MAJOR), "libavformat.so." SDFRT_STR(LIBAVFORMAT_VERSION_MAJOR)};

FfmpegApi load() {
  const std::string purpose = "writing a video";
  std::array<void*, 4> libs{};
  for (std::size_t i = 0; i < libs.size(); ++i) libs[i] = open_library(kLibraries[i], purpose);
  FfmpegApi api{};
#define SDFRT_FFMPEG_LOOKUP(lib, name) \
  api.name = reinterpret_cast<decltype(&::name)>(library_symbol(libs[lib], #name, purpose));
  SDFRT_FFMPEG_FUNCTIONS(SDFRT_FFMPEG_LOOKUP)
#undef SDFRT_FFMPEG_LOOKUP
  return api;
}

}  // namespace

const FfmpegApi& ffmpeg() {
  static const FfmpegApi api = load();
  return api;
}

}  // namespace sdfrt
