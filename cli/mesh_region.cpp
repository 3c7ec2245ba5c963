#include "mesh_region.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sdfc/kinds/registry.hpp"

namespace sdfc::cli {

namespace {
constexpr int kMaxVoxelsPerSide = 16384;  // beyond this a float grid loses the voxel's position
constexpr int kCutMargin = 2;             // voxels between the cut box and the grid's edge
}  // namespace

Region parse_bounds(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    size_t used = 0;
    double x = 0;
    try {
      x = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    while (used < part.size() && part[used] == ' ') ++used;
    if (used == 0 || used != part.size() || !std::isfinite(x))
      throw std::invalid_argument(fmt::format("--bounds: '{}' is not a number (expected x0,y0,z0,x1,y1,z1)", part));
    v.push_back(x);
  }
  if (v.size() != 6)
    throw std::invalid_argument(fmt::format("--bounds: expected 6 numbers x0,y0,z0,x1,y1,z1, got {}", v.size()));
  Region r{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
  for (int a = 0; a < 3; ++a)
    if (!(r.lo[a] < r.hi[a]))
      throw std::invalid_argument(fmt::format("--bounds: the {} range {}..{} is empty (each of x0,y0,z0 must be below "
                                              "its x1,y1,z1)", "xyz"[a], r.lo[a], r.hi[a]));
  return r;
}

Region scene_region(const ir::Module& m) {
  const ir::Box3& b = m.graph->node(m.root).props.bounds;
  if (!b.finite())
    throw std::invalid_argument(
        "the scene is unbounded (a plane, an infinite repeat or a half-space reaches infinity): give the region to "
        "mesh with --bounds x0,y0,z0,x1,y1,z1");
  if (b.empty()) throw std::invalid_argument("the scene holds no surface to mesh");
  double ext = 0;
  for (int a = 0; a < 3; ++a) ext = std::max(ext, b.hi[a] - b.lo[a]);
  Region r;
  for (int a = 0; a < 3; ++a) r.lo[a] = b.lo[a] - 0.02 * ext - 1e-6, r.hi[a] = b.hi[a] + 0.02 * ext + 1e-6;
  return r;
}

double default_iso(const ir::Module& m, double voxel) {
  for (ir::NodeId id : m.graph->postorder(m.root)) {
    const kinds::Description* d = kinds::find(m.graph->node(id).kind);
    if (d && d->escape_time) return 0.5 * voxel;
  }
  return 0;
}

sdfrt::mesh::GridSpec make_grid(const Region& r, int resolution, double voxel) {
  double ext = 0;
  for (int a = 0; a < 3; ++a) ext = std::max(ext, r.hi[a] - r.lo[a]);
  if (voxel <= 0) voxel = ext / resolution;
  sdfrt::mesh::GridSpec g;
  g.voxel = voxel;
  g.clip_lo = r.lo;
  g.clip_hi = r.hi;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil((r.hi[a] - r.lo[a]) / voxel) + 2 * kCutMargin;
    if (cells > kMaxVoxelsPerSide)
      throw std::invalid_argument(fmt::format("{} voxels along {} is more than {}: use a coarser --resolution or a larger "
                                              "--voxel", cells, "xyz"[a], kMaxVoxelsPerSide));
    // the cut faces fall halfway between voxel centres, where a plane's crossing is exact
    g.origin[a] = r.lo[a] - (kCutMargin - 0.5) * voxel;
    g.dims[a] = (int(cells) + sdfrt::mesh::kLeafDim - 1) / sdfrt::mesh::kLeafDim * sdfrt::mesh::kLeafDim;
  }
  return g;
}

}  // namespace sdfc::cli
