#include "viewer/frame_stats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace sdfc::viewer {

FrameStats frame_stats(std::vector<double> ms, double duration_s) {
  FrameStats s;
  s.frames = static_cast<int>(ms.size());
  s.duration_s = duration_s;
  if (ms.empty()) return s;
  std::sort(ms.begin(), ms.end());
  s.min_ms = ms.front();
  s.max_ms = ms.back();
  s.mean_ms = duration_s * 1000.0 / s.frames;
  s.fps = 1000.0 / s.mean_ms;
  std::size_t slow = std::max<std::size_t>(1, ms.size() / 100);
  double slow_mean = std::accumulate(ms.end() - slow, ms.end(), 0.0) / double(slow);
  s.one_percent_low_fps = 1000.0 / slow_mean;
  return s;
}

std::string format_frame_stats(const FrameStats& s, int width, int height, const std::string& device) {
  return fmt::format(
      "benchmark: {}x{} on {}\n"
      "  duration    {:.2f} s\n"
      "  frames      {}\n"
      "  mean        {:.1f} ms ({:.2f} fps)\n"
      "  min         {:.1f} ms ({:.2f} fps)\n"
      "  max         {:.1f} ms ({:.2f} fps)\n"
      "  1% low      {:.2f} fps\n",
      width, height, device, s.duration_s, s.frames, s.mean_ms, s.fps, s.min_ms,
      s.min_ms > 0 ? 1000.0 / s.min_ms : 0.0, s.max_ms, s.max_ms > 0 ? 1000.0 / s.max_ms : 0.0,
      s.one_percent_low_fps);
}

}  // namespace sdfc::viewer
