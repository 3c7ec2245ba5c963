#pragma once
// What a generated kernel and its host agree on: the per-frame parameter
// block the kernel reads from `frame`, and the output planes it writes, in
// order. The compiler emits these indices, codegen::frame_params fills the
// block, and the renderer, the command line and the viewer read the planes
// by these names.
#include <array>
#include <string_view>

namespace sdfc::abi {

// The frame block: floats the camera or time changes, so a new frame never
// recompiles. Each camera vector is three floats (the high part) followed by
// three floats of its remainder (the low part, kLowPart further on), so a
// double-precision kernel reads the camera to ~48 bits through a float buffer.
inline constexpr int kEye = 0;           // camera position
inline constexpr int kForward = 6;       // unit forward
inline constexpr int kRight = 12;        // right * tan(fov/2) * aspect
inline constexpr int kUp = 18;           // up * tan(fov/2)
inline constexpr int kLowPart = 3;       // a vector's low part follows its high part
inline constexpr int kPixelAngle = 24;   // 2 tan(fov/2) / height: pixel footprint per unit distance
inline constexpr int kTime = 25;         // seconds
inline constexpr int kFirstSample = 26;  // first anti-aliasing sample of this launch
inline constexpr int kSampleCount = 27;  // samples in it (progressive rendering launches them pass by pass)
inline constexpr int kFocus = 28;        // focus distance (depth of field)
inline constexpr int kFrameFloats = 32;  // length of the block

// The planes every kernel writes, then the ones it adds with AOVs.
inline constexpr std::array<std::string_view, 4> kImagePlanes = {"r", "g", "b", "depth"};
inline constexpr std::array<std::string_view, 7> kAovPlanes = {"normal_x", "normal_y", "normal_z", "steps",
                                                               "material", "iterations", "hit"};

// A path-traced kernel with AOVs adds the first hit's albedo (for
// denoisers), after the AOV planes.
inline constexpr std::array<std::string_view, 3> kPathAovPlanes = {"albedo_r", "albedo_g", "albedo_b"};

// The index of plane `name` in a kernel with AOVs (a path-traced one for
// the albedo), or -1.
constexpr int plane_index(std::string_view name) {
  for (size_t i = 0; i < kImagePlanes.size(); ++i)
    if (kImagePlanes[i] == name) return int(i);
  for (size_t i = 0; i < kAovPlanes.size(); ++i)
    if (kAovPlanes[i] == name) return int(kImagePlanes.size() + i);
  for (size_t i = 0; i < kPathAovPlanes.size(); ++i)
    if (kPathAovPlanes[i] == name) return int(kImagePlanes.size() + kAovPlanes.size() + i);
  return -1;
}

}  // namespace sdfc::abi
