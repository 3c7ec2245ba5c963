#pragma once
// The region and grid `sdfc mesh` samples: --bounds or the scene's inferred
// bounds, --resolution or --voxel, turned into a voxel grid.
#include <sdfrt/mesh/mesh.hpp>

#include <array>
#include <string>

#include "sdfc/ir/module.hpp"

namespace sdfc::cli {

struct Region {
  std::array<double, 3> lo, hi;
};

// "x0,y0,z0,x1,y1,z1", each lo below its hi; throws std::invalid_argument.
Region parse_bounds(const std::string& text);
// The scene's inferred bounds, padded so the cut never touches the surface;
// throws std::invalid_argument asking for --bounds when they are infinite.
Region scene_region(const ir::Module& m);
// The distance the surface is taken at: half a voxel where the scene holds
// an escape-time fractal (mandelbulb, mandelbox, julia, hybrid), whose
// estimate is good only outside the set and gives a dust of specks where
// it turns negative (a render likewise stops at its hit epsilon); else 0.
double default_iso(const ir::Module& m, double voxel);
// resolution: voxels along the longest side (used when voxel <= 0).
sdfrt::mesh::GridSpec make_grid(const Region& r, int resolution, double voxel);

}  // namespace sdfc::cli
