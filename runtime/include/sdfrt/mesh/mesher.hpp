#pragma once
// One frame's mesh: the narrow band, its blocks sampled slab by slab (one
// slab = the blocks of one x column of blocks), the level set, the mesh and
// its vertex colours.
#include <sdfrt/mesh/level_set.hpp>
#include <sdfrt/mesh/sampler.hpp>

#include <atomic>
#include <cstddef>
#include <functional>

namespace sdfrt::mesh {

struct MesherOptions {
  double adaptivity = 0;
  bool colour = false;
  double gamma = 2.2;   // colours are stored encoded, as renders are
  double slack = 1;     // see find_band
  bool dense = false;   // sample every block (the baseline)
  // Called once the band is known, with its memory estimate in bytes: throw to stop.
  std::function<void(std::size_t blocks, double bytes)> check_memory;
  std::function<void(int done, int total)> progress;  // slabs
  std::function<void(const char* stage)> stage;       // "meshing", "colouring": the steps after the slabs
  const std::atomic<bool>* cancel = nullptr;
};

struct MesherStats {
  std::size_t blocks = 0;     // sampled 8x8x8 blocks
  std::size_t grown = 0;      // of which found by following the surface out of the band
  std::size_t samples = 0;    // distance evaluations, the band search included
  std::size_t grid_bytes = 0; // the level set's memory
  bool unsigned_field = false; // no sample was negative
};

// Bytes per sampled block: its samples, the mesher's own per-voxel data and
// the mesh. The Mandelbulb at 1024 peaked at 6.2 KiB per block (3.1 GiB,
// 528k blocks); twice that, so the estimate errs on the safe side.
inline constexpr double kBytesPerBlock = 12 * 1024;

Mesh make_mesh(Sampler& sampler, const GridSpec& grid, const MesherOptions& opt, MesherStats* stats = nullptr);

}  // namespace sdfrt::mesh
