// The only file that includes OpenVDB (its headers are heavy to compile),
// built alone as the module libsdfc_openvdb.so. Samples go straight into
// leaf buffers; a signed flood fill gives the untouched space its
// inside/outside sign; volumeToMesh makes the polygons.

#include <openvdb/openvdb.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/level_set_backend.hpp"

namespace sdfrt::mesh {
namespace {

class OpenVdbLevelSet final : public LevelSetBackend {
 public:
  explicit OpenVdbLevelSet(const GridSpec& g);
  void add_block(const std::array<int, 3>& b, const float* samples) override;
  std::size_t blocks() const override;
  std::size_t memory_bytes() const override;
  float min_value() const override;
  Mesh to_mesh(double adaptivity) override;

 private:
  openvdb::FloatGrid::Ptr grid_;
  float background_ = 0;
  float min_value_ = std::numeric_limits<float>::infinity();
};

OpenVdbLevelSet::OpenVdbLevelSet(const GridSpec& g) {
  openvdb::initialize();
  // Wider than any sampled block's reach (half a block diagonal plus a
  // voxel), so clamping never changes a value the mesher interpolates.
  background_ = float(2 * kLeafDim * g.voxel);
  grid_ = openvdb::FloatGrid::create(background_);
  auto xf = openvdb::math::Transform::createLinearTransform(g.voxel);
  xf->postTranslate(openvdb::Vec3d(g.origin[0], g.origin[1], g.origin[2]));
  grid_->setTransform(xf);
  grid_->setGridClass(openvdb::GRID_LEVEL_SET);
}

void OpenVdbLevelSet::add_block(const std::array<int, 3>& b, const float* samples) {
  auto* leaf = grid_->tree().touchLeaf(openvdb::Coord(b[0] * kLeafDim, b[1] * kLeafDim, b[2] * kLeafDim));
  float* values = leaf->buffer().data();
  const float bg = background_;
  for (int i = 0; i < kLeafVoxels; ++i) {
    float v = samples[i];
    if (!std::isnan(v)) min_value_ = std::min(min_value_, v);
    values[i] = std::isnan(v) ? bg : std::clamp(v, -bg, bg);
  }
  leaf->setValuesOn();
}

std::size_t OpenVdbLevelSet::blocks() const { return grid_->tree().leafCount(); }

std::size_t OpenVdbLevelSet::memory_bytes() const { return grid_->memUsage(); }

float OpenVdbLevelSet::min_value() const { return min_value_; }

Mesh OpenVdbLevelSet::to_mesh(double adaptivity) {
  openvdb::tools::signedFloodFill(grid_->tree());
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid_, points, triangles, quads, 0.0, adaptivity, true);
  Mesh m;
  m.vertices.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) m.vertices[i] = {points[i].x(), points[i].y(), points[i].z()};
  points = {};
  // OpenVDB winds its polygons inwards for a level set: reverse them.
  m.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const auto& t : triangles) m.triangles.push_back({t[0], t[2], t[1]});
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[2], q[1]});
    m.triangles.push_back({q[0], q[3], q[2]});
  }
  return m;
}

}  // namespace
}  // namespace sdfrt::mesh

extern "C" __attribute__((visibility("default"))) sdfrt::mesh::LevelSetBackend* sdfc_openvdb_level_set(
    const sdfrt::mesh::GridSpec* grid) {
  return new sdfrt::mesh::OpenVdbLevelSet(*grid);
}
