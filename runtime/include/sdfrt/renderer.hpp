#pragma once
// Runs an sdfc kernel tile by tile and assembles a FloatImage.
//
// Kernel ABI (fixed, emitted by the compiler):
//   __kernel void sdfc_render(__global float* out, __global const float* frame,
//       const int img_w, const int img_h, const int tile_x0, const int tile_y0,
//       const int tile_w, const int tile_h, const int out_stride)
// A packet is pw x ph pixels (ph = packet_rows, pw = simd_width / ph).
// Work-item (gx, gy) covers pixels x = tile_x0 + gx*pw + lane % pw,
// y = tile_y0 + gy*ph + lane / pw and stores plane k of pixel
// (x-tile_x0, y-tile_y0) at out[k*out_stride*tile_h + (y-tile_y0)*out_stride + (x-tile_x0)].
// tile_w and tile_h are given rounded up to whole packets.
#include <sdfrt/device.hpp>
#include <sdfrt/float_image.hpp>
#include <sdfrt/program.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sdfrt {

constexpr int kMaxImageSide = 16384;

// Built with designated initialisers; every field has a default.
struct KernelSpec {
  std::string source = {};
  std::string entry = "sdfc_render";
  int simd_width = 1;
  int packet_rows = 1;              // pixel rows per packet; divides simd_width
  std::vector<std::string> planes = {};  // e.g. {"r","g","b","depth"}
  std::string build_options = {};
  // Numbers the kernel reads after the frame block it is given (the
  // compiler's object sets): uploaded with the first frame, behind it.
  std::vector<float> scene_data = {};
  // An environment map's buffer (background.map): uploaded once, passed as
  // the kernel's tenth argument `envmap`. Null: the kernel has nine.
  std::shared_ptr<const std::vector<float>> environment = {};
};

struct RenderOptions {
  int tile_width = 256;   // clamped at the image edges
  int tile_height = 256;
  std::function<void(int done, int total)> progress;  // called with (0,total) first, then per tile
  std::atomic<bool>* cancel = nullptr;               // checked before every launch (slices of ~100 ms)
  FloatImage* partial = nullptr;  // on cancel, receives the tiles done so far (the rest is zero)
  // Launch edge tiles with the full tile size too (tile_w/tile_h/out_stride
  // then describe the full tile; pixels past the image are computed and
  // dropped). PoCL compiles a work-group function per launch shape, so this
  // trades some wasted pixels for one compile instead of up to four.
  bool uniform_launch = false;
  // Render only the band of rows [row_begin, row_begin + row_count) of the
  // width x height image (row_count 0: to the bottom). The result is a
  // width x row_count image, so huge renders can stream band by band.
  int row_begin = 0;
  int row_count = 0;
  // A window of a larger image (a still's region on a render farm): the
  // kernel sees a full_width x full_height image and this call's width x
  // height pixels start at (x0, y0) of it. full_width 0: no window.
  struct Window {
    int full_width = 0, full_height = 0, x0 = 0, y0 = 0;
  } window;
};

struct RenderStats {
  double total_ms = 0.0;   // wall time of render()
  double kernel_ms = 0.0;  // sum of kernel execution times (profiling events)
  int tiles = 0;
};

class Renderer {
 public:
  // Builds the program once (through the binary cache). Throws BuildError.
  Renderer(Device& device, const KernelSpec& spec);

  // Renders the full image. Throws std::invalid_argument for bad sizes,
  // Cancelled when the cancel flag is set, DeviceError on OpenCL failures.
  FloatImage render(const std::vector<float>& frame, int width, int height,
                    const RenderOptions& options = {}, RenderStats* stats = nullptr);

  const BuildStats& build_stats() const noexcept { return build_stats_; }
  const RenderStats& last_render_stats() const noexcept { return last_stats_; }
  const KernelSpec& spec() const noexcept { return spec_; }
  Device& device() const noexcept { return *device_; }

 private:
  void ensure_out_buffer(std::size_t floats);
  void upload_frame(const std::vector<float>& frame);

  Device* device_;
  KernelSpec spec_;
  BuildStats build_stats_;
  std::optional<Program> program_;
  std::optional<Kernel> kernel_;
  BufferHandle out_buffer_;
  std::size_t out_buffer_floats_ = 0;
  // The output tile as read back; kept between calls (a render is many
  // bands and tiles), so its pages are touched once, not once per band.
  std::vector<float> host_tile_;
  BufferHandle env_buffer_;  // KernelSpec::environment, on the device
  BufferHandle frame_buffer_;
  std::size_t frame_buffer_floats_ = 0;
  std::size_t frame_head_floats_ = 0;  // the frame block's part of it; spec_.scene_data follows
  RenderStats last_stats_;
};

}  // namespace sdfrt
