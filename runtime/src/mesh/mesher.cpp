// One frame: band search, slab-by-slab block sampling into the level set,
// meshing, vertex colours.
#include <sdfrt/mesh/mesher.hpp>

#include <sdfrt/errors.hpp>
#include <sdfrt/mesh/narrow_band.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace sdfrt::mesh {

namespace {

std::uint8_t encode(float linear, double gamma) {
  double c = std::pow(std::clamp(double(linear), 0.0, 1.0), 1.0 / gamma);
  return std::uint8_t(std::lround(255.0 * c));
}

}  // namespace

Mesh make_mesh(Sampler& sampler, const GridSpec& grid, const MesherOptions& opt, MesherStats* stats) {
  sampler.set_grid(grid);
  MesherStats st;
  std::vector<std::array<int, 3>> band = find_band(sampler, grid, opt.slack, opt.dense);
  st.blocks = band.size();
  if (opt.check_memory) opt.check_memory(band.size(), double(band.size()) * kBytesPerBlock);
  // Slabs: the blocks of one x column, so progress moves evenly through the volume.
  std::sort(band.begin(), band.end());
  const int slabs = (grid.dims[0] + kLeafDim - 1) / kLeafDim;
  LevelSet level_set(grid);
  std::unordered_set<std::uint64_t> have, frontier;
  for (const auto& b : band) have.insert(block_key(b));
  // a crossing within reach of a block's side continues in the next block
  const double near = 2 * opt.slack * grid.voxel;
  auto sample = [&](const std::vector<std::array<int, 3>>& ids) {
    std::vector<float> samples = sampler.blocks(ids);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const float* v = samples.data() + i * kLeafVoxels;
      level_set.add_block(ids[i], v);
      add_frontier(ids[i], v, grid, near, have, frontier);
    }
  };
  std::size_t at = 0;
  for (int slab = 0; slab < slabs; ++slab) {
    if (opt.cancel && opt.cancel->load()) throw Cancelled();
    std::size_t end = at;
    while (end < band.size() && band[end][0] == slab) ++end;
    sample(std::vector<std::array<int, 3>>(band.begin() + at, band.begin() + end));
    at = end;
    if (opt.progress) opt.progress(slab + 1, slabs);
  }
  // follow the surface out of the band until it closes
  while (!frontier.empty() && !opt.dense) {
    if (opt.cancel && opt.cancel->load()) throw Cancelled();
    std::vector<std::array<int, 3>> ids;
    for (std::uint64_t k : frontier) {
      have.insert(k);
      ids.push_back(block_of_key(k));
    }
    frontier.clear();
    st.grown += ids.size();
    band.insert(band.end(), ids.begin(), ids.end());
    sample(ids);
  }
  st.blocks = band.size();
  st.samples = band.size() * kLeafVoxels;
  st.grid_bytes = level_set.memory_bytes();
  st.unsigned_field = !(level_set.min_value() + grid.iso < 0);
  if (opt.stage) opt.stage("meshing");
  Mesh m = level_set.to_mesh(opt.adaptivity);
  if (opt.colour && !m.vertices.empty()) {
    if (opt.stage) opt.stage("colouring");
    std::vector<Vec3f> albedo = sampler.albedo(m.vertices);
    m.colours.resize(albedo.size());
    for (std::size_t i = 0; i < albedo.size(); ++i)
      for (int c = 0; c < 3; ++c) m.colours[i][c] = encode(albedo[i][c], opt.gamma);
  }
  if (stats) *stats = st;
  return m;
}

}  // namespace sdfrt::mesh
