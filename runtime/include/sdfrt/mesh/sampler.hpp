#pragma once
// Runs the sdfc_mesh_* entries of a scene's mesh kernel (see
// sdfc/codegen/emit_mesh_kernels.hpp) on an OpenCL device.
#include <sdfrt/device.hpp>
#include <sdfrt/mesh/mesh.hpp>
#include <sdfrt/program.hpp>

#include <optional>
#include <string>
#include <vector>

namespace sdfrt::mesh {

class Sampler {
 public:
  // Builds `source` (through the binary cache); simd_width is what it was emitted for.
  // scene_data: the kernel's object-set numbers (EmittedKernel::scene_data), after the grid block.
  Sampler(Device& device, const std::string& source, int simd_width, BuildStats* stats = nullptr,
          std::vector<float> scene_data = {});
  void set_grid(const GridSpec& grid);  // every later call samples on this grid, at its time

  // The clipped distance at each point.
  std::vector<float> distances(const std::vector<Vec3f>& points);
  // The clipped distance at every voxel of each 8x8x8 block (block coordinates
  // = voxel / 8), 512 per block in OpenVDB's leaf order.
  std::vector<float> blocks(const std::vector<std::array<int, 3>>& blocks);
  // The linear albedo at each point.
  std::vector<Vec3f> albedo(const std::vector<Vec3f>& points);

 private:
  std::vector<float> run_points(Kernel& k, const std::vector<Vec3f>& points, int planes);
  Device* device_;
  int width_;
  Program program_;
  Kernel points_, blocks_, colour_;
  std::vector<float> grid_;
  std::vector<float> scene_data_;
};

}  // namespace sdfrt::mesh
