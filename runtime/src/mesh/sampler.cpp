// Host side of the mesh kernel's entries: buffers, launches, read-back.
// Large requests go in chunks so the device never holds more than a few
// tens of megabytes at once.
#include <sdfrt/mesh/sampler.hpp>

#include <fmt/format.h>

#include <algorithm>

#include "device/cl_check.hpp"

namespace sdfrt::mesh {

namespace {

constexpr std::size_t kChunkPoints = 1 << 20;   // points per launch
constexpr std::size_t kChunkBlocks = 1 << 13;   // blocks per launch (16 MiB of samples)

BufferHandle make_buffer(Device& d, cl_mem_flags flags, std::size_t bytes, const void* host, const char* what) {
  cl_int status = CL_SUCCESS;
  BufferHandle b(clCreateBuffer(d.context(), flags | (host ? CL_MEM_COPY_HOST_PTR : 0), std::max<std::size_t>(bytes, 4),
                                const_cast<void*>(host), &status));
  check_cl(status, fmt::format("clCreateBuffer({}, {} bytes)", what, bytes));
  return b;
}

void launch(Device& d, Kernel& k, std::size_t items) {
  check_cl(clEnqueueNDRangeKernel(d.queue(), k.get(), 1, nullptr, &items, nullptr, 0, nullptr, nullptr),
           fmt::format("clEnqueueNDRangeKernel({}, {} work-items)", k.name(), items));
}

void read(Device& d, BufferHandle& b, std::size_t bytes, void* host) {
  check_cl(clEnqueueReadBuffer(d.queue(), b.get(), CL_TRUE, 0, bytes, host, 0, nullptr, nullptr), "clEnqueueReadBuffer(mesh samples)");
}

}  // namespace

Sampler::Sampler(Device& device, const std::string& source, int simd_width, BuildStats* stats,
                 std::vector<float> scene_data)
    : device_(&device),
      width_(simd_width),
      program_(build_program(device, source, "", stats)),
      points_(program_.kernel("sdfc_mesh_points")),
      blocks_(program_.kernel("sdfc_mesh_blocks")),
      colour_(program_.kernel("sdfc_mesh_colour")),
      scene_data_(std::move(scene_data)) {
  set_grid(GridSpec{});
}

void Sampler::set_grid(const GridSpec& g) {
  grid_ = {float(g.origin[0]),  float(g.origin[1]),  float(g.origin[2]),  float(g.voxel),
           float(g.clip_lo[0]), float(g.clip_lo[1]), float(g.clip_lo[2]), float(g.clip_hi[0]),
           float(g.clip_hi[1]), float(g.clip_hi[2]), float(g.time), float(g.iso)};
  grid_.insert(grid_.end(), scene_data_.begin(), scene_data_.end());  // the kernel reads it at g + 12
}

// planes: 1 (distance) or 3 (colour, which also takes the padded count n).
std::vector<float> Sampler::run_points(Kernel& k, const std::vector<Vec3f>& points, int planes) {
  std::vector<float> result(points.size() * planes);
  BufferHandle grid = make_buffer(*device_, CL_MEM_READ_ONLY, grid_.size() * 4, grid_.data(), "grid");
  for (std::size_t first = 0; first < points.size(); first += kChunkPoints) {
    const std::size_t count = std::min(kChunkPoints, points.size() - first);
    const std::size_t n = (count + width_ - 1) / width_ * width_;  // whole packets; the tail repeats the last point
    std::vector<float> xyz(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) xyz[c * n + i] = points[first + std::min(i, count - 1)][c];
    BufferHandle px = make_buffer(*device_, CL_MEM_READ_ONLY, n * 4, xyz.data(), "x");
    BufferHandle py = make_buffer(*device_, CL_MEM_READ_ONLY, n * 4, xyz.data() + n, "y");
    BufferHandle pz = make_buffer(*device_, CL_MEM_READ_ONLY, n * 4, xyz.data() + 2 * n, "z");
    BufferHandle out = make_buffer(*device_, CL_MEM_WRITE_ONLY, n * 4 * planes, nullptr, "samples");
    cl_mem args[4] = {px.get(), py.get(), pz.get(), out.get()};
    for (unsigned i = 0; i < 4; ++i) k.set_arg(i, args[i]);
    unsigned next = 4;
    if (planes > 1) k.set_arg(next++, cl_int(n));
    k.set_arg(next, grid.get());
    launch(*device_, k, n / width_);
    std::vector<float> got(n * planes);
    read(*device_, out, got.size() * 4, got.data());
    for (int p = 0; p < planes; ++p)
      for (std::size_t i = 0; i < count; ++i) result[(first + i) * planes + p] = got[p * n + i];
  }
  return result;
}

std::vector<float> Sampler::distances(const std::vector<Vec3f>& points) { return run_points(points_, points, 1); }

std::vector<Vec3f> Sampler::albedo(const std::vector<Vec3f>& points) {
  std::vector<float> flat = run_points(colour_, points, 3);
  std::vector<Vec3f> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  return out;
}

std::vector<float> Sampler::blocks(const std::vector<std::array<int, 3>>& blocks) {
  std::vector<float> result(blocks.size() * kLeafVoxels);
  BufferHandle grid = make_buffer(*device_, CL_MEM_READ_ONLY, grid_.size() * 4, grid_.data(), "grid");
  for (std::size_t first = 0; first < blocks.size(); first += kChunkBlocks) {
    const std::size_t count = std::min(kChunkBlocks, blocks.size() - first);
    BufferHandle ids = make_buffer(*device_, CL_MEM_READ_ONLY, count * 12, blocks[first].data(), "blocks");
    BufferHandle out = make_buffer(*device_, CL_MEM_WRITE_ONLY, count * kLeafVoxels * 4, nullptr, "block samples");
    blocks_.set_arg(0, ids.get());
    blocks_.set_arg(1, out.get());
    blocks_.set_arg(2, grid.get());
    launch(*device_, blocks_, count * (kLeafVoxels / width_));
    read(*device_, out, count * kLeafVoxels * 4, result.data() + first * kLeafVoxels);
  }
  return result;
}

}  // namespace sdfrt::mesh
