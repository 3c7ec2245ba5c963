// Meshes of shapes whose volume, area and topology are known, made by the
// real pipeline: the emitted kernel on PoCL, the narrow band, OpenVDB.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "mesh_support.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace {

using sdfc::test::mesh_scene;
constexpr double kPi = 3.14159265358979323846;

void expect_closed_and_oriented(const sdfrt::mesh::Mesh& m) {
  auto t = sdfrt::mesh::check_topology(m);
  EXPECT_TRUE(t.watertight()) << t.open_edges << " open, " << t.overshared_edges << " over-shared edges";
  EXPECT_TRUE(t.oriented()) << t.misoriented_edges << " misoriented edges";
  EXPECT_EQ(t.degenerate_triangles, 0u);
}

TEST(MeshShapes, SphereVolumeAndAreaWithinHalfAPercentAt256) {
  auto r = mesh_scene("scene: {sphere: {radius: 1}}\n", 256);
  const double v = sdfrt::mesh::volume(r.mesh), a = sdfrt::mesh::area(r.mesh);
  EXPECT_NEAR(v / (4.0 / 3.0 * kPi), 1.0, 0.005) << "volume " << v;
  EXPECT_NEAR(a / (4 * kPi), 1.0, 0.005) << "area " << a;
  expect_closed_and_oriented(r.mesh);
  EXPECT_EQ(sdfrt::mesh::check_topology(r.mesh).euler, 2);
  // the narrow band: the blocks near the shell, a small part of the grid
  const double dense = double(r.grid.dims[0]) * r.grid.dims[1] * r.grid.dims[2];
  EXPECT_LT(double(r.stats.samples), 0.25 * dense);
}

TEST(MeshShapes, TorusHasGenusOneAndIsWatertight) {
  auto r = mesh_scene("scene: {torus: {major_radius: 1, minor_radius: 0.3}}\n", 64);
  expect_closed_and_oriented(r.mesh);
  auto t = sdfrt::mesh::check_topology(r.mesh);
  EXPECT_EQ(t.euler, 0);
  EXPECT_EQ(t.parts, 1u);
  EXPECT_NEAR(sdfrt::mesh::volume(r.mesh) / (2 * kPi * kPi * 1.0 * 0.09), 1.0, 0.02);
}

TEST(MeshShapes, AdaptivityMergesPolygonsAndKeepsTheTorusClosed) {
  const char* torus = "scene: {torus: {major_radius: 1, minor_radius: 0.3}}\n";
  auto fine = mesh_scene(torus, 96);
  auto merged = mesh_scene(torus, 96, std::nullopt, false, false, 0.5);
  EXPECT_LT(merged.mesh.triangles.size(), fine.mesh.triangles.size() / 2);
  expect_closed_and_oriented(merged.mesh);
  EXPECT_EQ(sdfrt::mesh::check_topology(merged.mesh).euler, 0);
  // merged polygons cut across curved parts: about 10 % of the volume here
  EXPECT_NEAR(sdfrt::mesh::volume(merged.mesh) / (2 * kPi * kPi * 1.0 * 0.09), 1.0, 0.15);
  EXPECT_NEAR(sdfrt::mesh::volume(fine.mesh) / (2 * kPi * kPi * 1.0 * 0.09), 1.0, 0.01);
}

// The narrow band samples fewer distances than the dense grid and gives
// the same mesh.
TEST(MeshShapes, NarrowBandGivesTheDenseGridsMesh) {
  const char* yaml = "scene: {smooth_union: {radius: 0.3, children: [{sphere: {}}, {box: {size: [1, 1, 3]}}]}}\n";
  auto band = mesh_scene(yaml, 64);
  auto dense = mesh_scene(yaml, 64, std::nullopt, false, true);
  EXPECT_LT(band.stats.samples, dense.stats.samples / 2);
  EXPECT_EQ(band.mesh.triangles.size(), dense.mesh.triangles.size());
  EXPECT_NEAR(sdfrt::mesh::volume(band.mesh), sdfrt::mesh::volume(dense.mesh), 1e-9);
}

// A box with a spherical bite and a bar through it, against the
// reference evaluator's inside/outside on a dense grid of points.
TEST(MeshShapes, CsgSceneMatchesBruteForceDenseSampling) {
  const char* yaml = R"(scene:
  union:
    - difference: [{box: {size: [1.6, 1.6, 1.6]}}, {sphere: {radius: 0.9}, translate: [0.8, 0.8, 0.8]}]
    - {box: {size: [2.6, 0.4, 0.4]}, rotate: [0, 0, 30]}
)";
  auto r = mesh_scene(yaml, 96);
  expect_closed_and_oriented(r.mesh);
  const auto& m = r.module;
  const sdfc::ir::Box3& b = m.graph->node(m.root).props.bounds;
  const int n = 120;
  long inside = 0;
  double cell[3];
  for (int a = 0; a < 3; ++a) cell[a] = (b.hi[a] - b.lo[a]) / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        sdfc::reference::Vec3 p{b.lo[0] + (i + 0.5) * cell[0], b.lo[1] + (j + 0.5) * cell[1], b.lo[2] + (k + 0.5) * cell[2]};
        inside += sdfc::reference::distance(m, p) < 0;
      }
  const double brute = inside * cell[0] * cell[1] * cell[2];
  EXPECT_NEAR(sdfrt::mesh::volume(r.mesh) / brute, 1.0, 0.01) << "brute force " << brute;
  // every vertex lies on the reference's surface, to within a voxel
  double worst = 0;
  for (const auto& v : r.mesh.vertices) worst = std::max(worst, std::fabs(sdfc::reference::distance(m, {v[0], v[1], v[2]})));
  EXPECT_LT(worst, r.grid.voxel);
}

// The Euler characteristic of the sponge's surface, counted on its cubes:
// twice that of the solid (V - E + F - C of the closed unit cubes).
long menger_surface_euler(int level) {
  int n = 1;
  for (int i = 0; i < level; ++i) n *= 3;
  auto solid = [&](int i, int j, int k) {
    for (int l = 0; l < level; ++l, i /= 3, j /= 3, k /= 3)
      if ((i % 3 == 1) + (j % 3 == 1) + (k % 3 == 1) >= 2) return false;
    return true;
  };
  std::set<std::array<int, 4>> v, e, f;  // position and axis (v: axis 0)
  long cubes = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        if (!solid(i, j, k)) continue;
        ++cubes;
        for (int c = 0; c < 8; ++c) v.insert({i + (c >> 2), j + ((c >> 1) & 1), k + (c & 1), 0});
        for (int ax = 0; ax < 3; ++ax)
          for (int c = 0; c < 4; ++c) {
            std::array<int, 4> edge{i, j, k, ax}, face{i, j, k, ax};
            edge[(ax + 1) % 3] += c & 1;
            edge[(ax + 2) % 3] += c >> 1;
            e.insert(edge);
            face[ax] += c & 1;
            if (c < 2) f.insert(face);
          }
      }
  return 2 * (long(v.size()) - long(e.size()) + long(f.size()) - cubes);
}

// Bounds of exactly the sponge's cube at a multiple of 27 voxels put every
// face of the level-3 holes halfway between voxel centres.
TEST(MeshShapes, MengerSpongeLevelThreeWithinOnePercentOfItsVolume) {
  auto r = mesh_scene("scene: {menger: {iterations: 3, scale: 3}}\n", 81, sdfc::cli::Region{{-1, -1, -1}, {1, 1, 1}});
  const double analytic = 8.0 * std::pow(20.0 / 27.0, 3);
  EXPECT_NEAR(sdfrt::mesh::volume(r.mesh) / analytic, 1.0, 0.01) << "volume " << sdfrt::mesh::volume(r.mesh);
  expect_closed_and_oriented(r.mesh);
  EXPECT_EQ(sdfrt::mesh::check_topology(r.mesh).euler, menger_surface_euler(3));
}

}  // namespace
