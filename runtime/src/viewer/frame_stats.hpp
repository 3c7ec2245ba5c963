#pragma once
// Frame-time statistics of a benchmark run (seed 004, section 5.2).
#include <string>
#include <vector>

namespace sdfc::viewer {

struct FrameStats {
  int frames = 0;
  double duration_s = 0;
  double mean_ms = 0;  // duration / frames, as section 5.2 defines it
  double min_ms = 0, max_ms = 0;
  double one_percent_low_fps = 0;  // fps over the slowest 1% of frames (at least one)
  double fps = 0;                  // 1000 / mean_ms
};

FrameStats frame_stats(std::vector<double> frame_ms, double duration_s);
// Multi-line report: resolution, device and the statistics above.
std::string format_frame_stats(const FrameStats& s, int width, int height, const std::string& device);

}  // namespace sdfc::viewer
