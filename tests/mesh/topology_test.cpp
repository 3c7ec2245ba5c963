// The topology checker on meshes small enough to know by hand, so the
// shape tests can trust it.
#include <gtest/gtest.h>
#include <sdfrt/mesh/topology.hpp>

#include <cmath>

namespace {

using sdfrt::mesh::Mesh;

// A tetrahedron wound outwards: (0,0,0), (1,0,0), (0,1,0), (0,0,1).
Mesh tetrahedron() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

TEST(MeshTopology, ClosedTetrahedronIsWatertightOrientedSphere) {
  Mesh m = tetrahedron();
  auto t = sdfrt::mesh::check_topology(m);
  EXPECT_TRUE(t.watertight());
  EXPECT_TRUE(t.oriented());
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.parts, 1u);
  EXPECT_EQ(t.euler, 2);
  EXPECT_NEAR(sdfrt::mesh::volume(m), 1.0 / 6, 1e-9);
  EXPECT_NEAR(sdfrt::mesh::area(m), 1.5 + std::sqrt(3.0) / 2, 1e-6);
}

TEST(MeshTopology, FlippedFaceIsMisoriented) {
  Mesh m = tetrahedron();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  auto t = sdfrt::mesh::check_topology(m);
  EXPECT_TRUE(t.watertight());
  EXPECT_FALSE(t.oriented());
  EXPECT_EQ(t.misoriented_edges, 3u);
}

TEST(MeshTopology, MissingFaceLeavesOpenEdges) {
  Mesh m = tetrahedron();
  m.triangles.pop_back();
  auto t = sdfrt::mesh::check_topology(m);
  EXPECT_FALSE(t.watertight());
  EXPECT_EQ(t.open_edges, 3u);
  EXPECT_EQ(t.euler, 1);  // a disc
}

TEST(MeshTopology, TwoTetrahedraAreTwoParts) {
  Mesh m = tetrahedron();
  for (int i = 0; i < 4; ++i) m.vertices.push_back({m.vertices[i][0] + 5, m.vertices[i][1], m.vertices[i][2]});
  for (int i = 0; i < 4; ++i) {
    auto t = m.triangles[i];
    m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  }
  auto t = sdfrt::mesh::check_topology(m);
  EXPECT_EQ(t.parts, 2u);
  EXPECT_EQ(t.euler, 4);
  EXPECT_NEAR(sdfrt::mesh::volume(m), 2.0 / 6, 1e-9);
}

}  // namespace
