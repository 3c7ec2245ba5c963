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
// stdlib): a scene with an object set that sees the world's points (below
// the root through unions, bounding boxes and materials alone, passes_cone),
// seen through a pinhole by the direct integrator, whose march feeds
// nothing but the hit (no glow, no occlusion from the step count, no
// bisection). Their steps change with the cone; the hits do not.
bool camera_cones(const ir::Module& m);
// Whether a node hands the cone on to its children: it neither moves the
// point (a transform, a domain operation) nor blends or cuts its children's
// surfaces, so the items outside the cone stay out of the rays' way. A set
// below any other node is walked whole.
bool passes_cone(ir::Kind k);

// With camera cones and a single object set, its items in each packet's
// cone are listed once (os_list_gather) and the camera march measures them
// from the list (os_union_list): the call that gathers them, or empty.
std::string camera_list_gather(const ir::Module& m);

// Whether the normals' taps bound the scene's distance from above
// (scene_dist_below, normal_*_below in the stdlib): the top of the scene is
// an object set, or a union of one (its last child) with exact shapes, so
// the distance is 1-Lipschitz (no fractal estimate, nothing divided by L).
// A tap lies within |e| of the hit, so the scene is at most d(hit) + |e|
// there, and the walk opens only the boxes that near: the same value, from
// a few boxes. A bounding box around the scene (a `bounded` root) keeps
// this where it matters: near a hit, inside the box's margin, the distance
// is the scene's; a miss's normal is thrown away.
bool bounded_normals(const ir::Module& m);
// Whether the segment shades its hits with bounded normals: bounded_normals,
// with finite-difference normals and one material per point (no blends).
bool bounded_shading(const ir::Module& m);
// With bounded_shading, at a hit `pos` (lanes `hit`, finite-difference step
// `h`): the material into `id` (declared before) and the distance d_hit,
// then the normal n from taps bounded by d_hit. The set is read through
// `cone`, an os_cone expression (os_cone_none() walks it).
void emit_bounded_hit(CodeWriter& w, const ir::Module& m, const Literals& lit, std::set<std::string>& used,
                      const std::string& cone);
// Whether, besides, the packet's list (camera_list_gather) answers the
// hits' material and normal taps (os_union_shade): the list then holds a
// cone wider by the farthest tap's angle.
bool shading_from_list(const ir::Module& m);
// The scene below a bounding box at the root, else the root: the node that
// sees scene_dist_below's bound.
ir::NodeId top_of_scene(const ir::Module& m);

// The prelude's addition: scene functions take the buffer after the time.
std::string scene_data_macros(bool animated, int unlocked);

}  // namespace sdfc::codegen::detail
