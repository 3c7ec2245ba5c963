#include <sdfrt/renderer.hpp>

#include "device/cl_check.hpp"
#include "renderer/launch_shape.hpp"
#include "renderer/tile_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstring>
#include <stdexcept>

namespace sdfrt {
namespace {

int ceil_div(int a, int b) { return (a + b - 1) / b; }

double ms_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double event_ms(cl_event event) {
  cl_ulong start = 0, end = 0;
  check_cl(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_START, sizeof(start), &start, nullptr),
           "clGetEventProfilingInfo(START)");
  check_cl(clGetEventProfilingInfo(event, CL_PROFILING_COMMAND_END, sizeof(end), &end, nullptr),
           "clGetEventProfilingInfo(END)");
  return end > start ? static_cast<double>(end - start) * 1e-6 : 0.0;
}

// Argument indices of the fixed kernel ABI.
enum Arg : unsigned { kOut, kFrame, kImgW, kImgH, kTileX0, kTileY0, kTileW, kTileH, kOutStride, kEnvironment };

}  // namespace

Renderer::Renderer(Device& device, const KernelSpec& spec) : device_(&device), spec_(spec) {
  if (spec_.simd_width < 1) {
    throw std::invalid_argument(
        fmt::format("KernelSpec.simd_width must be at least 1, got {}", spec_.simd_width));
  }
  if (spec_.packet_rows < 1 || spec_.simd_width % spec_.packet_rows != 0) {
    throw std::invalid_argument(fmt::format("KernelSpec.packet_rows must divide simd_width {}, got {}",
                                            spec_.simd_width, spec_.packet_rows));
  }
  if (spec_.planes.empty()) {
    throw std::invalid_argument("KernelSpec.planes is empty: the kernel must output at least one plane");
  }
  program_.emplace(build_program(device, spec_.source, spec_.build_options, &build_stats_));
  kernel_.emplace(program_->kernel(spec_.entry));
  if (spec_.environment && !spec_.environment->empty()) {
    cl_int status = CL_SUCCESS;
    const std::size_t bytes = spec_.environment->size() * sizeof(float);
    env_buffer_.reset(clCreateBuffer(device_->context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                                     const_cast<float*>(spec_.environment->data()), &status));
    check_cl(status, fmt::format("clCreateBuffer(environment map, {} bytes)", bytes));
  }
}

void Renderer::ensure_out_buffer(std::size_t floats) {
  if (out_buffer_ && out_buffer_floats_ >= floats) return;
  cl_int status = CL_SUCCESS;
  out_buffer_.reset();  // free the old one first; device memory may be tight
  out_buffer_floats_ = 0;
  out_buffer_.reset(clCreateBuffer(device_->context(), CL_MEM_WRITE_ONLY, floats * sizeof(float),
                                   nullptr, &status));
  check_cl(status, fmt::format("clCreateBuffer(output tile, {} bytes)", floats * sizeof(float)));
  out_buffer_floats_ = floats;
}

void Renderer::upload_frame(const std::vector<float>& frame) {
  // An empty frame still needs a valid buffer argument.
  const std::size_t head = std::max<std::size_t>(frame.size(), 1);
  const std::vector<float>& data = spec_.scene_data;
  const std::size_t floats = head + data.size();
  cl_int status = CL_SUCCESS;
  if (!frame_buffer_ || frame_buffer_floats_ != floats || frame_head_floats_ != head) {
    frame_buffer_.reset();
    frame_buffer_.reset(clCreateBuffer(device_->context(), CL_MEM_READ_ONLY,
                                       floats * sizeof(float), nullptr, &status));
    check_cl(status, "clCreateBuffer(frame parameters)");
    frame_buffer_floats_ = floats;
    frame_head_floats_ = head;
    if (!data.empty())  // written once: frames change only the block in front of it
      check_cl(clEnqueueWriteBuffer(device_->queue(), frame_buffer_.get(), CL_TRUE, head * sizeof(float),
                                    data.size() * sizeof(float), data.data(), 0, nullptr, nullptr),
               "clEnqueueWriteBuffer(scene data)");
  }
  const float zero = 0.0f;
  const void* src = frame.empty() ? &zero : frame.data();
  check_cl(clEnqueueWriteBuffer(device_->queue(), frame_buffer_.get(), CL_TRUE, 0,
                                head * sizeof(float), src, 0, nullptr, nullptr),
           "clEnqueueWriteBuffer(frame parameters)");
}

FloatImage Renderer::render(const std::vector<float>& frame, int width, int height,
                            const RenderOptions& options, RenderStats* stats_out) {
  const auto start = std::chrono::steady_clock::now();
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw std::invalid_argument(fmt::format("image size {}x{} is outside 1..{}", width, height, kMaxImageSide));
  const int band_rows = options.row_count > 0 ? options.row_count : height - options.row_begin;
  if (options.row_begin < 0 || band_rows < 1 || options.row_begin + band_rows > height)
    throw std::invalid_argument(fmt::format("rows {}..{} are outside the image's {} rows", options.row_begin,
                                            options.row_begin + band_rows, height));
  const RenderOptions::Window& win = options.window;
  const bool windowed = win.full_width > 0;
  if (windowed && (win.x0 < 0 || win.y0 < 0 || win.x0 + width > win.full_width || win.y0 + height > win.full_height ||
                   win.full_width > kMaxImageSide || win.full_height > kMaxImageSide))
    throw std::invalid_argument(fmt::format("a {}x{} window at {},{} is outside the {}x{} image", width, height, win.x0,
                                            win.y0, win.full_width, win.full_height));
  // Tiles are planned over the band; the kernel sees image rows.
  const TilePlan plan = plan_tiles(width, band_rows, options.tile_width, options.tile_height);
  const int ph = spec_.packet_rows;
  const int pw = spec_.simd_width / ph;
  const std::size_t planes = spec_.planes.size();

  // The largest tile decides the buffer; refuse before allocating anything.
  const std::size_t max_stride = static_cast<std::size_t>(ceil_div(plan.max_width, pw)) * pw;
  const std::size_t max_rows = static_cast<std::size_t>(ceil_div(plan.max_height, ph)) * ph;
  const std::size_t max_floats = planes * max_stride * max_rows;
  const std::uint64_t max_bytes = max_floats * sizeof(float);
  if (max_bytes > device_->info().max_alloc_bytes) {
    throw std::invalid_argument(fmt::format(
        "a {}x{} tile with {} planes needs a {:.1f} MiB buffer, more than the device's maximum "
        "allocation of {:.1f} MiB; use smaller tiles",
        plan.max_width, plan.max_height, planes, max_bytes / 1048576.0,
        device_->info().max_alloc_bytes / 1048576.0));
  }
  if (max_floats > static_cast<std::size_t>(INT_MAX)) {
    // The kernel indexes `out` with int arithmetic.
    throw std::invalid_argument(fmt::format(
        "a {}x{} tile with {} planes has more than 2^31 samples; use smaller tiles",
        plan.max_width, plan.max_height, planes));
  }

  FloatImage image(width, band_rows, spec_.planes);
  ensure_out_buffer(max_floats);
  upload_frame(frame);

  Kernel& kernel = *kernel_;
  cl_mem out = out_buffer_.get();
  cl_mem frame_mem = frame_buffer_.get();
  kernel.set_arg(kOut, out);
  kernel.set_arg(kFrame, frame_mem);
  if (env_buffer_) {
    cl_mem env = env_buffer_.get();
    kernel.set_arg(kEnvironment, env);
  }
  kernel.set_arg(kImgW, static_cast<cl_int>(windowed ? win.full_width : width));
  kernel.set_arg(kImgH, static_cast<cl_int>(windowed ? win.full_height : height));

  RenderStats stats;
  const int total = static_cast<int>(plan.tiles.size());
  if (options.progress) options.progress(0, total);
  if (host_tile_.size() < max_floats) host_tile_.resize(max_floats);
  std::vector<float>& host = host_tile_;

  // Renders the w x h pixels at (x0, y0) of the band in one launch into the image.
  auto launch_slice = [&](int x0, int y0, int w, int h) {
    // What the kernel is told and launched with: the slice itself, or the
    // full tile size when uniform (the excess lands in ignored rows/lanes).
    const int launch_w = options.uniform_launch ? plan.max_width : w;
    const int launch_h = options.uniform_launch ? plan.max_height : h;
    const int groups_x = ceil_div(launch_w, pw);
    const int groups_y = ceil_div(launch_h, ph);
    const int stride = groups_x * pw;
    const int rows = groups_y * ph;  // whole packets; the excess rows are dropped
    kernel.set_arg(kTileX0, static_cast<cl_int>(x0 + win.x0));
    kernel.set_arg(kTileY0, static_cast<cl_int>(y0 + options.row_begin + win.y0));
    kernel.set_arg(kTileW, static_cast<cl_int>(stride));
    kernel.set_arg(kTileH, static_cast<cl_int>(rows));
    kernel.set_arg(kOutStride, static_cast<cl_int>(stride));
    const std::size_t global[2] = {static_cast<std::size_t>(groups_x), static_cast<std::size_t>(groups_y)};
    const auto local = launch_local_size(device_->info().type);
    cl_event raw_event = nullptr;
    check_cl(clEnqueueNDRangeKernel(device_->queue(), kernel.get(), 2, nullptr, global,
                                    local ? local->data() : nullptr, 0, nullptr, &raw_event),
             fmt::format("clEnqueueNDRangeKernel({}, tile {}x{} at {},{})", kernel.name(), w, h, x0, y0));
    EventHandle event(raw_event);
    const std::size_t tile_floats = planes * static_cast<std::size_t>(stride) * static_cast<std::size_t>(rows);
    // Blocking read on an in-order queue also waits for the kernel.
    check_cl(clEnqueueReadBuffer(device_->queue(), out, CL_TRUE, 0, tile_floats * sizeof(float), host.data(), 0,
                                 nullptr, nullptr),
             "clEnqueueReadBuffer(output tile)");
    stats.kernel_ms += event_ms(event.get());
    // Drop the padding lanes while copying rows into the image.
    for (std::size_t k = 0; k < planes; ++k) {
      auto dst = image.plane(static_cast<int>(k));
      for (int row = 0; row < h; ++row) {
        const float* src = host.data() + (k * static_cast<std::size_t>(rows) + static_cast<std::size_t>(row)) *
                                             static_cast<std::size_t>(stride);
        float* to = dst.data() + static_cast<std::size_t>(y0 + row) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x0);
        std::memcpy(to, src, static_cast<std::size_t>(w) * sizeof(float));
      }
    }
  };

  // A tile is launched in slices (one packet at first, doubling while a
  // launch takes under 50 ms, halving past 200 ms), so the cancel flag is
  // seen within a fraction of a second even where one tile takes minutes.
  int slice_w = pw, slice_h = ph;
  for (int t = 0; t < total; ++t) {
    const Tile& tile = plan.tiles[static_cast<std::size_t>(t)];
    for (int sy = 0; sy < tile.height;) {
      const int band_h = options.uniform_launch ? tile.height : std::min(slice_h, tile.height - sy);
      for (int sx = 0; sx < tile.width;) {
        if (options.cancel && options.cancel->load()) {
          if (options.partial) *options.partial = std::move(image);
          throw Cancelled();
        }
        const int part_w = options.uniform_launch ? tile.width : std::min(slice_w, tile.width - sx);
        const auto slice_start = std::chrono::steady_clock::now();
        launch_slice(tile.x0 + sx, tile.y0 + sy, part_w, band_h);
        sx += part_w;
        const double ms = ms_between(slice_start, std::chrono::steady_clock::now());
        if (ms < 50) {
          if (slice_w < plan.max_width) slice_w *= 2;
          else if (slice_h < plan.max_height) slice_h *= 2;
        } else if (ms > 200) {
          if (slice_h > ph) slice_h = std::max(ph, slice_h / 2 / ph * ph);
          else if (slice_w > pw) slice_w = std::max(pw, slice_w / 2 / pw * pw);
        }
      }
      sy += band_h;
    }
    if (options.progress) options.progress(t + 1, total);
  }

  stats.tiles = total;
  stats.total_ms = ms_between(start, std::chrono::steady_clock::now());
  last_stats_ = stats;
  if (stats_out) *stats_out = stats;
  return image;
}

}  // namespace sdfrt
