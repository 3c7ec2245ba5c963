#pragma once
// Which 8x8x8 blocks of the grid the surface may cross, found coarse to
// fine: a cell whose centre distance exceeds its half-diagonal (plus one
// voxel diagonal, so every voxel next to a crossing is sampled) holds no
// surface, because the distance is a lower bound. Only the remaining
// cells are split, so the work follows the surface area, not the volume.
#include <sdfrt/mesh/sampler.hpp>

#include <array>
#include <vector>

namespace sdfrt::mesh {

// slack multiplies the half-diagonal test (1 for distance bounds; more for
// fractal distance estimates, which may overestimate). dense: every block
// (the baseline the narrow band is measured against). iso: the distance
// the surface is taken at.
std::vector<std::array<int, 3>> find_band(Sampler& sampler, const GridSpec& grid, double slack, bool dense = false,
                                          double iso = 0);

}  // namespace sdfrt::mesh
