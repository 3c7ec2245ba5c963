#pragma once
// Renders scene text on the default OpenCL device, and maps world points to
// pixels, so tests can check effects where geometry says they must show.
#include <sdfrt/device.hpp>
#include <sdfrt/float_image.hpp>
#include <sdfrt/renderer.hpp>

#include <optional>
#include <string>

#include "sdfc/ir/module.hpp"

namespace sdfc::test {

sdfrt::Device& device();
ir::Module compile_text(const std::string& scene);

struct Rendered {
  ir::Module module;
  sdfrt::FloatImage image;
};
// Renders with 16-lane packets (the CPU default), AOV planes included.
// packet_rows 0: the emitter's default shape (4x4 at width 16).
Rendered render_text(const std::string& scene, int simd_width = 16, int tile = 256, int packet_rows = 0);
// The same for a compiled module (a test may change its plan first).
Rendered render_module(ir::Module module, int simd_width = 16, int tile = 256, int packet_rows = 0);

// The pixel (column, row) the camera of `plan` sees world point p in.
struct Pixel {
  int x, y;
};
Pixel project(const ir::RenderPlan& plan, ir::Vec3d p);

// The world point a pixel's centre ray hits, from the depth plane (plane 3);
// nullopt on a miss.
std::optional<ir::Vec3d> world_point(const Rendered& r, int x, int y);

// Linear luminance-like mean of r, g, b at a pixel.
float brightness(const sdfrt::FloatImage& img, Pixel px);

}  // namespace sdfc::test
