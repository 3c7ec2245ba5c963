#pragma once
// Emits one OpenCL C kernel for a module. The generated kernel follows the
// runtime's ABI (sdfrt/renderer.hpp):
//   __kernel void sdfc_render(__global float* out, __global const float* frame,
//       int img_w, int img_h, int tile_x0, int tile_y0, int tile_w, int tile_h, int out_stride)
// Each work-item shades a packet of `simd_width` pixels (a tile of
// packet_rows rows): the stdlib is written
// over `real`/`vec3`/`mask`, which the prelude defines per width and precision.
#include <memory>
#include <string>
#include <vector>

#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen {

struct EmitOptions {
  int simd_width = 1;  // 1 (GPUs, one pixel per work-item) or 2/4/8/16/32/64 (CPU packets)
  bool probe_kernel = false;  // also emit sdfc_probe, which evaluates the distance at given points
  bool aovs = false;          // also store normal_x/y/z, steps and material planes after r, g, b, depth
  // Pixel rows per packet, a power of two dividing simd_width; 0 picks
  // default_packet_rows: packets as square as they come (4x4, 8x4, 8x8),
  // which keeps their rays coherent.
  int packet_rows = 0;
  bool alpha = false;   // a camera ray that misses adds no colour: the colour is premultiplied by the hit plane
  bool linear = false;  // store the linear colour (after exposure, before the tone curve and gamma), for EXR
  bool steps_plane = false;  // without aovs: store only the steps plane after r, g, b, depth (the viewer's overlay)
  // Kernels appended after the render kernel (the mesh sampler's entries); they may call
  // anything the render kernel holds.
  std::string extra_entries = {};
};

struct EmittedKernel {
  std::string source;
  std::string entry = "sdfc_render";
  int simd_width = 1;
  int packet_rows = 1;              // the packet is (simd_width / packet_rows) x packet_rows pixels
  std::vector<std::string> planes;  // output planes, in order
  int frame_floats = 0;             // length of the frame parameter block
  // Object sets' numbers (sdfc/ir/object_set.hpp): the renderer puts them in
  // the frame buffer after the frame block and the unlocked values.
  std::vector<float> scene_data;
  std::vector<std::string> stdlib_functions;  // which stdlib functions it holds
  // background.map with the path integrator: the buffer for the kernel's
  // last argument, `envmap` (ir::EnvironmentMap::data); null without one.
  std::shared_ptr<const std::vector<float>> environment;
};

EmittedKernel emit_opencl(const ir::Module& m, const EmitOptions& opt = {});

// The packet rows emit_opencl picks for a width: 4 at 16 and 32, 8 at 64, else 1.
int default_packet_rows(int simd_width);

// The frame parameter block (camera basis, pixel angle, time) the kernel
// reads from `frame`; computed on the host per frame, so moving the camera
// never recompiles. Its layout is sdfc/codegen/kernel_abi.hpp.
std::vector<float> frame_params(const ir::RenderPlan& plan, int width, int height, double time = 0);
inline constexpr int kFrameFloats = abi::kFrameFloats;

}  // namespace sdfc::codegen
