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

std::vector<std::array<int, 3>> find_band(Sampler& sampler, const GridSpec& g, double slack, bool dense) {
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
        if (!(std::fabs(d[i]) > reach)) kept.push_back(cells[i]);  // NaN: keep, it may hide a surface
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

std::uint64_t block_key(const std::array<int, 3>& b) {
  return std::uint64_t(b[0]) << 42 | std::uint64_t(b[1]) << 21 | std::uint64_t(b[2]);
}

std::array<int, 3> block_of_key(std::uint64_t k) {
  return {int(k >> 42), int((k >> 21) & 0x1fffff), int(k & 0x1fffff)};
}

void add_frontier(const std::array<int, 3>& b, const float* v, const GridSpec& g, double near,
                  const std::unordered_set<std::uint64_t>& have, std::unordered_set<std::uint64_t>& out) {
  const int last = kLeafDim - 1;
  for (int x = 0; x < kLeafDim; ++x)
    for (int y = 0; y < kLeafDim; ++y)
      for (int z = 0; z < kLeafDim; ++z) {
        const bool side = x == 0 || x == last || y == 0 || y == last || z == 0 || z == last;
        if (!side) continue;
        const float s = v[(x * kLeafDim + y) * kLeafDim + z];  // OpenVDB's leaf order
        if (std::fabs(s) > near) continue;  // NaN falls through: it may hide a surface
        const int lo[3] = {x == 0 ? -1 : 0, y == 0 ? -1 : 0, z == 0 ? -1 : 0};
        const int hi[3] = {x == last ? 1 : 0, y == last ? 1 : 0, z == last ? 1 : 0};
        for (int dx = lo[0]; dx <= hi[0]; ++dx)
          for (int dy = lo[1]; dy <= hi[1]; ++dy)
            for (int dz = lo[2]; dz <= hi[2]; ++dz) {
              const std::array<int, 3> n{b[0] + dx, b[1] + dy, b[2] + dz};
              bool inside = true;
              for (int a = 0; a < 3; ++a) inside = inside && n[a] >= 0 && n[a] * kLeafDim < g.dims[a];
              if (!inside || (dx == 0 && dy == 0 && dz == 0)) continue;
              const std::uint64_t key = block_key(n);
              if (!have.count(key)) out.insert(key);
            }
      }
}

}  // namespace sdfrt::mesh
