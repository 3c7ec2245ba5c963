#pragma once
// Which 8x8x8 blocks of the grid the surface may cross, found coarse to
// fine: a cell whose centre distance exceeds its half-diagonal (plus one
// voxel diagonal, so every voxel next to a crossing is sampled) holds no
// surface, because the distance is a lower bound. Only the remaining
// cells are split, so the work follows the surface area, not the volume.
#include <sdfrt/mesh/sampler.hpp>

#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace sdfrt::mesh {

// slack multiplies the half-diagonal test (1 for distance bounds; more for
// fractal distance estimates, which may overestimate). dense: every block
// (the baseline the narrow band is measured against).
std::vector<std::array<int, 3>> find_band(Sampler& sampler, const GridSpec& grid, double slack, bool dense = false);

// The unsampled neighbours of sampled blocks that the surface runs into: a
// voxel on a block's side within `near` of the surface (or NaN) adds
// the blocks beyond that side. Sampling them, and theirs in turn, follows
// the surface wherever a distance estimate overstated the distance, so no
// piece of it is left out of the band (which would open the mesh).
// `have` holds every block sampled so far, by block_key().
std::uint64_t block_key(const std::array<int, 3>& b);
void add_frontier(const std::array<int, 3>& block, const float* samples, const GridSpec& grid, double near,
                  const std::unordered_set<std::uint64_t>& have, std::unordered_set<std::uint64_t>& out);
std::array<int, 3> block_of_key(std::uint64_t key);

}  // namespace sdfrt::mesh
