#pragma once
// Schema of the primitive catalogue (cone ... box_frame): names, parameters,
// validation, lowering to IR.
#include <optional>
#include <string_view>
#include <vector>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::frontend {

const std::vector<std::string_view>& catalogue_kinds();

// The node for a catalogue primitive (kNoNode after an error), or nullopt
// when `key` names no catalogue primitive.
std::optional<ir::NodeId> lower_catalogue(ValueReader& r, ir::Builder& b, const SourceValue& key,
                                          const SourceValue& body);

}  // namespace sdfc::frontend
