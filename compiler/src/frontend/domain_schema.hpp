#pragma once
// Schema of the domain operations (modifier keys: repeat, mirror, twist, ...)
// and of the blends (smooth_* kinds and hg_sdf's chamfer/round/columns/stairs).
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::frontend {

// Modifier keys, in the order they apply to the shape (innermost first).
const std::vector<std::string_view>& domain_modifiers();
// Wraps `n` in the domain operations `node` names.
ir::NodeId apply_domain_modifiers(ValueReader& r, ir::Builder& b, const SourceValue& node, ir::NodeId n);

const std::vector<std::string_view>& blend_kinds();
// Lowers `children` of `body` into `kind` with `params` (a smooth blend's
// radius may be animated).
using ChildLowering = std::function<ir::NodeId(ir::Kind, const SourceValue& list, std::vector<Param> params)>;
// A blend node (kNoNode after an error), or nullopt when key names no blend
// handled here; smooth_* with kind: polynomial is left to the caller.
std::optional<ir::NodeId> lower_blend(ValueReader& r, const SourceValue& key, const SourceValue& body,
                                      const ChildLowering& children);

}  // namespace sdfc::frontend
