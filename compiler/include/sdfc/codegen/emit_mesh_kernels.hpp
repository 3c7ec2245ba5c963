#pragma once
// The kernel `sdfc mesh` samples: the scene's render kernel (the same
// specialised distance and material code) with three more entries.
// Every entry reads `grid`, a block of 12 floats: voxel (0,0,0)'s world
// position [0..2], the voxel size [3], the box the solid is cut to
// (lo [4..6], hi [7..9]), the frame time [10] and the distance from the
// scene's surface the mesh's surface is taken at [11] (its iso value).
//   sdfc_mesh_points(px, py, pz, out, grid): the distance at given points
//     (n a multiple of simd_width; one work-item per simd_width points).
//   sdfc_mesh_blocks(blocks, out, grid): the distance at every voxel of
//     8x8x8 blocks (blocks: 3 ints per block, its voxel (0,0,0) / 8); out
//     holds 512 floats per block in OpenVDB's leaf order (x slowest, z
//     fastest); 512 / simd_width work-items per block.
//   sdfc_mesh_colour(px, py, pz, out, n, grid): the surface albedo at given
//     points (orbit-trap palettes and blended materials included), linear,
//     as three planes of n floats.
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc::codegen {

inline constexpr int kMeshGridFloats = 12;

EmittedKernel emit_mesh_kernels(const ir::Module& m, int simd_width);

}  // namespace sdfc::codegen
