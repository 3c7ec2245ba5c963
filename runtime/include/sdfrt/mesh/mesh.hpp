#pragma once
// A triangle mesh and the voxel grid it is sampled on (sdfc mesh).
#include <array>
#include <cstdint>
#include <vector>

namespace sdfrt::mesh {

// Voxel (i, j, k) sits at origin + (i, j, k) * voxel. dims are multiples of
// 8 (OpenVDB's leaf size). The solid is cut to [clip_lo, clip_hi], which
// lies inside the grid, so a cut solid is closed.
struct GridSpec {
  std::array<double, 3> origin{0, 0, 0};
  double voxel = 1;
  std::array<int, 3> dims{8, 8, 8};
  std::array<double, 3> clip_lo{0, 0, 0}, clip_hi{0, 0, 0};
  double time = 0;  // the frame time of an animated scene
  double iso = 0;   // the surface is taken at this distance from the scene's
};
inline constexpr int kLeafDim = 8;  // voxels per side of a sampled block
inline constexpr int kLeafVoxels = kLeafDim * kLeafDim * kLeafDim;

using Vec3f = std::array<float, 3>;
using Tri = std::array<std::uint32_t, 3>;  // counter-clockwise seen from outside
using Rgb8 = std::array<std::uint8_t, 3>;

struct Mesh {
  std::vector<Vec3f> vertices;
  std::vector<Tri> triangles;
  std::vector<Rgb8> colours;  // empty, or one per vertex
};

}  // namespace sdfrt::mesh
