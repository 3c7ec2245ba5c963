#pragma once
// The sampled blocks as an OpenVDB level set, and its mesh. OpenVDB's
// headers stay in level_set.cpp: this header is all the rest sees.
#include <sdfrt/mesh/mesh.hpp>

#include <cstddef>
#include <memory>

namespace sdfrt::mesh {

class LevelSet {
 public:
  explicit LevelSet(const GridSpec& grid);
  ~LevelSet();
  LevelSet(const LevelSet&) = delete;
  LevelSet& operator=(const LevelSet&) = delete;

  // One block's 512 samples (OpenVDB leaf order), block coordinates = voxel / 8.
  void add_block(const std::array<int, 3>& block, const float* samples);
  std::size_t blocks() const;
  std::size_t memory_bytes() const;
  float min_value() const;  // the smallest sample added (+inf before any)
  // volumeToMesh at 0 (the samples already hold the iso offset); adaptivity
  // 0 keeps every polygon, up to 1 merges flat regions. Quads are split into triangles, wound outwards.
  Mesh to_mesh(double adaptivity);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sdfrt::mesh
