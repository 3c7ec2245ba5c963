#pragma once
// The interface between LevelSet (level_set.cpp, in every program) and its
// OpenVDB implementation (openvdb_level_set.cpp, the module
// lib/sdfc/libsdfc_openvdb.so, opened the first time a mesh is made: OpenVDB
// and its libraries cost every process ~60 ms to load).
#include <sdfrt/mesh/level_set.hpp>

namespace sdfrt::mesh {

class LevelSetBackend {
 public:
  virtual ~LevelSetBackend() = default;
  virtual void add_block(const std::array<int, 3>& block, const float* samples) = 0;
  virtual std::size_t blocks() const = 0;
  virtual std::size_t memory_bytes() const = 0;
  virtual float min_value() const = 0;
  virtual Mesh to_mesh(double adaptivity) = 0;
};

}  // namespace sdfrt::mesh

// The module's one entry point: a new level set for the grid.
#define SDFC_OPENVDB_MODULE "libsdfc_openvdb.so"
#define SDFC_OPENVDB_ENTRY "sdfc_openvdb_level_set"
extern "C" sdfrt::mesh::LevelSetBackend* sdfc_openvdb_level_set(const sdfrt::mesh::GridSpec* grid);
