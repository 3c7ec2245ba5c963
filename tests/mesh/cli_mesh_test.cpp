// `sdfc mesh` as a user runs it: the three formats read back by the tests'
// own readers, colours, sequences, and bad input failing cleanly.
#include <gtest/gtest.h>
#include <sdfrt/mesh/topology.hpp>

#include <cmath>
#include <filesystem>
#include <set>

#include "mesh_readers.hpp"
#include "run_sdfc.hpp"

namespace {

using sdfc::test::run_sdfc;
using sdfc::test::ScratchDir;
namespace fs = std::filesystem;

const char* kSphere = "scene: {sphere: {radius: 1}}\n";

TEST(MeshCli, StlObjAndPlyHoldTheSameClosedMesh) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kSphere);
  for (const char* ext : {"stl", "obj", "ply"}) {
    auto r = run_sdfc("mesh " + scene + " --resolution 32 -o " + dir.file(std::string("s.") + ext));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("triangles"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find(std::string("s.") + ext), std::string::npos) << r.out;
  }
  auto stl = sdfc::test::read_stl(dir.file("s.stl"));
  auto obj = sdfc::test::read_obj(dir.file("s.obj"));
  auto ply = sdfc::test::read_ply(dir.file("s.ply"));
  ASSERT_GT(ply.triangles.size(), 1000u);
  EXPECT_EQ(obj.triangles, ply.triangles);
  EXPECT_EQ(obj.vertices, ply.vertices);  // OBJ's shortest decimal form reads back to the same float
  ASSERT_EQ(stl.triangles.size(), ply.triangles.size());
  for (size_t t = 0; t < ply.triangles.size(); ++t)
    for (int v = 0; v < 3; ++v) ASSERT_EQ(stl.vertices[stl.triangles[t][v]], ply.vertices[ply.triangles[t][v]]) << t;
  for (const auto* m : {&stl, &ply}) {
    auto topo = sdfrt::mesh::check_topology(*m);
    EXPECT_TRUE(topo.watertight());
    EXPECT_TRUE(topo.oriented());
    EXPECT_EQ(topo.euler, 2);
  }
  EXPECT_NEAR(sdfrt::mesh::volume(ply) / (4.0 / 3.0 * 3.14159265358979), 1.0, 0.03);
}

TEST(MeshCli, ColoursComeFromTheMaterials) {
  ScratchDir dir;
  std::string scene = dir.write("two.yaml", R"(materials:
  red: {color: [0.8, 0.1, 0.1]}
  blue: {color: [0.1, 0.2, 0.9]}
scene:
  union:
    - {sphere: {radius: 0.5}, translate: [-0.7, 0, 0], material: red}
    - {sphere: {radius: 0.5}, translate: [0.7, 0, 0], material: blue}
)");
  for (const char* ext : {"ply", "obj"}) {
    auto r = run_sdfc("mesh " + scene + " --resolution 48 --colour -o " + dir.file(std::string("two.") + ext));
    ASSERT_EQ(r.code, 0) << r.err;
  }
  auto ply = sdfc::test::read_ply(dir.file("two.ply"));
  auto obj = sdfc::test::read_obj(dir.file("two.obj"));
  ASSERT_EQ(ply.colours.size(), ply.vertices.size());
  EXPECT_EQ(obj.colours, ply.colours);
  // gamma-encoded like a render: 255 * c^(1/2.2)
  auto enc = [](double c) { return int(std::lround(255 * std::pow(c, 1 / 2.2))); };
  for (size_t i = 0; i < ply.vertices.size(); ++i) {
    const bool left = ply.vertices[i][0] < 0;
    const double want[3] = {left ? 0.8 : 0.1, left ? 0.1 : 0.2, left ? 0.1 : 0.9};
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(int(ply.colours[i][c]), enc(want[c]), 1) << "vertex " << i;
  }
}

TEST(MeshCli, IsoOffsetsTheSurface) {
  ScratchDir dir;
  auto r = run_sdfc("mesh " + dir.write("s.yaml", kSphere) + " --resolution 48 --bounds -1.5,-1.5,-1.5,1.5,1.5,1.5 "
                    "--iso 0.25 -o " + dir.file("s.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto m = sdfc::test::read_ply(dir.file("s.ply"));
  EXPECT_NEAR(sdfrt::mesh::volume(m) / (4.0 / 3.0 * 3.14159265358979 * 1.25 * 1.25 * 1.25), 1.0, 0.01);
}

TEST(MeshCli, OrbitTrapColoursVaryOverAFractal) {
  ScratchDir dir;
  auto r = run_sdfc("mesh bench/scenes/mandelbulb-1280.yaml --resolution 48 --colour -o " + dir.file("b.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("half a voxel"), std::string::npos) << r.err;
  auto m = sdfc::test::read_ply(dir.file("b.ply"));
  std::set<sdfrt::mesh::Rgb8> distinct(m.colours.begin(), m.colours.end());
  EXPECT_GT(distinct.size(), 50u);  // the palette, not one flat material colour
}

// A smooth union of two materials: the colour of the kernel's blended
// material record, pure on the far sides and mixed at the seam.
TEST(MeshCli, BlendedMaterialsMixAtTheSeam) {
  ScratchDir dir;
  std::string scene = dir.write("blend.yaml", R"(materials:
  red: {color: [0.8, 0.1, 0.1]}
  blue: {color: [0.1, 0.2, 0.9]}
scene:
  smooth_union:
    radius: 0.4
    children:
      - {sphere: {radius: 0.5}, translate: [-0.4, 0, 0], material: red}
      - {sphere: {radius: 0.5}, translate: [0.4, 0, 0], material: blue}
)");
  auto r = run_sdfc("mesh " + scene + " --resolution 48 --colour -o " + dir.file("b.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto m = sdfc::test::read_ply(dir.file("b.ply"));
  int far_red = 0, far_blue = 0, seam = 0;
  for (size_t i = 0; i < m.vertices.size(); ++i) {
    const float x = m.vertices[i][0];
    const auto& c = m.colours[i];
    if (x < -0.8f) far_red += c[0] > 200 && c[2] < 120;
    if (x > 0.8f) far_blue += c[2] > 200 && c[0] < 120;
    if (std::fabs(x) < 0.02f) seam += c[0] > 140 && c[0] < 210 && c[2] > 150 && c[2] < 220;
  }
  EXPECT_GT(far_red, 10);
  EXPECT_GT(far_blue, 10);
  EXPECT_GT(seam, 10);
}

TEST(MeshCli, StlWarnsThatItHoldsNoColour) {
  ScratchDir dir;
  auto r = run_sdfc("mesh " + dir.write("s.yaml", kSphere) + " --resolution 16 --colour -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("no colours"), std::string::npos) << r.err;
}

TEST(MeshCli, FramesWriteOneMeshPerFrame) {
  ScratchDir dir;
  std::string scene = dir.write("grow.yaml", "scene: {sphere: {radius: \"0.5 + 0.25 * time\"}}\n");
  auto r = run_sdfc("mesh " + scene + " --resolution 24 --bounds -1.2,-1.2,-1.2,1.2,1.2,1.2 --frames 0:2 --fps 1 -o " +
                    dir.file("seq/f_%02d.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  double last = 0;
  for (int f = 0; f <= 2; ++f) {
    auto m = sdfc::test::read_ply(dir.file("seq/f_0" + std::to_string(f) + ".ply"));
    const double radius = 0.5 + 0.25 * f, v = sdfrt::mesh::volume(m);
    EXPECT_NEAR(v / (4.0 / 3.0 * 3.14159265358979 * radius * radius * radius), 1.0, 0.05) << "frame " << f;
    EXPECT_GT(v, last);
    last = v;
  }
}

TEST(MeshCli, UnboundedSceneAsksForBoundsAndIsCutClosedByThem) {
  ScratchDir dir;
  std::string scene = dir.write("floor.yaml", "scene: {plane: {normal: [0, 0, 1], offset: 0}}\n");
  auto r = run_sdfc("mesh " + scene + " -o " + dir.file("f.stl"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--bounds"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("f.stl")));
  r = run_sdfc("mesh " + scene + " --bounds -1,-1,-1,1,1,1 --resolution 64 -o " + dir.file("f.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  auto m = sdfc::test::read_ply(dir.file("f.ply"));
  EXPECT_TRUE(sdfrt::mesh::check_topology(m).watertight());
  EXPECT_NEAR(sdfrt::mesh::volume(m) / 4.0, 1.0, 0.01);  // the lower half of the cube
  // an offset surface moves the floor, not the cut
  r = run_sdfc("mesh " + scene + " --bounds -1,-1,-1,1,1,1 --resolution 64 --iso 0.25 -o " + dir.file("g.ply"));
  ASSERT_EQ(r.code, 0) << r.err;
  m = sdfc::test::read_ply(dir.file("g.ply"));
  float lo = 0, hi = 0;
  for (const auto& v : m.vertices) lo = std::min(lo, v[0]), hi = std::max(hi, v[0]);
  EXPECT_NEAR(lo, -1.0, 1e-4);
  EXPECT_NEAR(hi, 1.0, 1e-4);
  EXPECT_NEAR(sdfrt::mesh::volume(m) / 5.0, 1.0, 0.01);  // 2 x 2 x 1.25
}

TEST(MeshCli, BadBoundsFailWithWhatWasExpected) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kSphere);
  auto r = run_sdfc("mesh " + scene + " --bounds 1,2,3 -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("expected 6 numbers"), std::string::npos) << r.err;
  r = run_sdfc("mesh " + scene + " --bounds 0,0,0,-1,1,1 -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("is empty"), std::string::npos) << r.err;
  r = run_sdfc("mesh " + scene + " --bounds 0,0,0,1,one,1 -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'one' is not a number"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("s.stl")));
}

TEST(MeshCli, UnwritableOutputAndUnknownFormatFailCleanly) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kSphere);
  auto r = run_sdfc("mesh " + scene + " --resolution 16 -o " + dir.file("missing/dir/s.stl"));
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("missing/dir/s.stl"), std::string::npos) << r.err;
  r = run_sdfc("mesh " + scene + " -o " + dir.file("s.xyz"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(".stl, .obj or .ply"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() + "/missing"));  // nothing created, no temp file left
}

TEST(MeshCli, RefusesAMeshOverTheMemoryLimitUnlessForced) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kSphere);
  auto r = run_sdfc("mesh " + scene + " --resolution 64 --memory-limit 0.0001 -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("s.stl")));
  r = run_sdfc("mesh " + scene + " --resolution 64 --memory-limit 0.0001 --force -o " + dir.file("s.stl"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("s.stl")));
}

TEST(MeshCli, HelpNamesTheOptions) {
  auto r = run_sdfc("mesh --help");
  EXPECT_EQ(r.code, 0);
  for (const char* o : {"--resolution", "--voxel", "--bounds", "--adaptivity", "--colour", "--frames", "--force"})
    EXPECT_NE(r.out.find(o), std::string::npos) << o;
}

}  // namespace
