#pragma once
#include <string>

#include "sdfc/ir/graph.hpp"

namespace sdfc::frontend {

// The name a node has in the scene file (the IR merges some: every hg_sdf
// blend is one blend_* kind, a list scale is scale_xyz), for messages.
std::string scene_name(const ir::Node& n);

}  // namespace sdfc::frontend
