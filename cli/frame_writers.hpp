#pragma once
// The files of one rendered frame, fed with bands of the kernel's planes:
// the beauty image in its format (PNG, JPEG, PFM, EXR, or the next frame of
// a video) and, beside a PNG/JPEG/PFM, the AOVs as PFM files. An EXR holds
// the AOVs itself as named channels.
#include <sdfrt/float_image.hpp>
#include <sdfrt/renderer.hpp>
#include <sdfrt/stream_writers.hpp>

#include <memory>
#include <string>
#include <vector>

#include "offline_render.hpp"

namespace sdfc::cli {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // The next rows of the frame, from the top, with the kernel's planes.
  virtual void write_band(const sdfrt::FloatImage& band) = 0;
  // Commits every file; returns the paths written (none for a video frame).
  virtual std::vector<std::string> finish() = 0;
  // A stopped render: commits the beauty image alone under `path`, the
  // rows not written black. Returns the path.
  virtual std::string finish_partial(const std::string& path) = 0;
};

// `gamma` is the kernel's display gamma (PNG alpha is straightened through it).
std::unique_ptr<FrameSink> open_frame_sink(const sdfrt::KernelSpec& spec, int width, int height, float gamma,
                                           const OfflineOutput& out);

// The EXR channels of a kernel: R, G, B (half unless bit_depth is 32), A
// (the hit coverage, with alpha), and one per AOV: Z, N.X/N.Y/N.Z, steps,
// iterations, material, hit (float).
std::vector<sdfrt::ExrChannel> exr_channels(const sdfrt::KernelSpec& spec, const OfflineOutput& out);

}  // namespace sdfc::cli
