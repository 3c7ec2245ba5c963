// One frame: band search, slab-by-slab block sampling into the level set,
// meshing, vertex colours.
#include <sdfrt/mesh/mesher.hpp>

#include <sdfrt/errors.hpp>
#include <sdfrt/mesh/narrow_band.hpp>

#include <algorithm>
#include <cmath>

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
  const double band_iso = opt.iso;
  std::vector<std::array<int, 3>> band = find_band(sampler, grid, opt.slack, opt.dense, band_iso);
  st.blocks = band.size();
  if (opt.check_memory) opt.check_memory(band.size(), double(band.size()) * kBytesPerBlock);
  // Slabs: the blocks of one x column, so progress moves evenly through the volume.
  std::sort(band.begin(), band.end());
  const int slabs = (grid.dims[0] + kLeafDim - 1) / kLeafDim;
  LevelSet level_set(grid, band_iso);
  std::size_t at = 0;
  for (int slab = 0; slab < slabs; ++slab) {
    if (opt.cancel && opt.cancel->load()) throw Cancelled();
    std::size_t end = at;
    while (end < band.size() && band[end][0] == slab) ++end;
    std::vector<std::array<int, 3>> ids(band.begin() + at, band.begin() + end);
    std::vector<float> samples = sampler.blocks(ids);
    for (std::size_t i = 0; i < ids.size(); ++i) level_set.add_block(ids[i], samples.data() + i * kLeafVoxels);
    at = end;
    if (opt.progress) opt.progress(slab + 1, slabs);
  }
  st.samples = band.size() * kLeafVoxels;
  st.grid_bytes = level_set.memory_bytes();
  st.unsigned_field = !(level_set.min_value() < 0);
  st.iso = band_iso;
  Mesh m = level_set.to_mesh(opt.adaptivity);
  if (opt.colour && !m.vertices.empty()) {
    std::vector<Vec3f> albedo = sampler.albedo(m.vertices);
    m.colours.resize(albedo.size());
    for (std::size_t i = 0; i < albedo.size(); ++i)
      for (int c = 0; c < 3; ++c) m.colours[i][c] = encode(albedo[i][c], opt.gamma);
  }
  if (stats) *stats = st;
  return m;
}

}  // namespace sdfrt::mesh
