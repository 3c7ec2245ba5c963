#pragma once
// Object sets in the kernel (sdfc/ir/object_set.hpp): the scene data buffer
// that holds their numbers. Their walk is kinds/object_set.cpp.
#include <set>
#include <string>
#include <vector>

#include "code_writer.hpp"
#include "sdfc/ir/module.hpp"

namespace sdfc::codegen::detail {

// Every object set's floats at its offset: what follows the frame block (and
// the unlocked values) in the frame buffer. Empty without object sets.
std::vector<float> scene_data(const ir::Module& m);
bool has_object_sets(const ir::Module& m);

// Whether the camera rays march in their packet's cone (os_cone in the
// stdlib): a scene with object sets seen through a pinhole by the direct
// integrator, whose march feeds nothing but the hit (no glow, no occlusion
// from the step count, no bisection). Their steps change with the cone; the
// hits do not.
bool camera_cones(const ir::Module& m);

// The prelude's addition: scene functions take the buffer after the time.
std::string scene_data_macros(bool animated, int unlocked);

}  // namespace sdfc::codegen::detail
