// Coarse-to-fine search for the blocks the surface may cross. Cells start
// at 64 voxels a side and halve down to the 8-voxel blocks OpenVDB stores.
#include <sdfrt/mesh/narrow_band.hpp>

#include <cmath>

namespace sdfrt::mesh {

namespace {

constexpr int kTopCell = 64;  // voxels per side of the coarsest cells

using Cell = std::array<int, 3>;  // in units of the current cell size

// The world position of the centre of the voxel centres a cell covers.
Vec3f centre(const GridSpec& g, const Cell& c, int size) {
  Vec3f p;
  for (int a = 0; a < 3; ++a) p[a] = float(g.origin[a] + (c[a] * size + 0.5 * (size - 1)) * g.voxel);
  return p;
}

bool inside_grid(const GridSpec& g, const Cell& c, int size) {
  for (int a = 0; a < 3; ++a)
    if (c[a] * size >= g.dims[a]) return false;
  return true;
}

}  // namespace

std::vector<std::array<int, 3>> find_band(Sampler& sampler, const GridSpec& g, double slack, bool dense, double iso) {
  std::vector<Cell> cells;
  int size = kTopCell;
  for (int i = 0; i * size < g.dims[0]; ++i)
    for (int j = 0; j * size < g.dims[1]; ++j)
      for (int k = 0; k * size < g.dims[2]; ++k) cells.push_back({i, j, k});
  while (true) {
    if (!dense) {
      std::vector<Vec3f> points;
      points.reserve(cells.size());
      for (const Cell& c : cells) points.push_back(centre(g, c, size));
      std::vector<float> d = sampler.distances(points);
      // half the diagonal of the voxel centres, plus one voxel diagonal: a
      // sign change on an edge leaving the cell still finds the cell sampled
      const double reach = slack * std::sqrt(3.0) * g.voxel * (0.5 * (size - 1) + 1.0);
      std::vector<Cell> kept;
      for (std::size_t i = 0; i < cells.size(); ++i)
        if (!(std::fabs(d[i] - iso) > reach)) kept.push_back(cells[i]);  // NaN: keep, it may hide a surface
      cells.swap(kept);
    }
    if (size == kLeafDim) return cells;
    std::vector<Cell> children;
    children.reserve(cells.size() * 8);
    size /= 2;
    for (const Cell& c : cells)
      for (int o = 0; o < 8; ++o) {
        Cell ch{2 * c[0] + (o >> 2), 2 * c[1] + ((o >> 1) & 1), 2 * c[2] + (o & 1)};
        if (inside_grid(g, ch, size)) children.push_back(ch);
      }
    cells.swap(children);
  }
}

}  // namespace sdfrt::mesh
