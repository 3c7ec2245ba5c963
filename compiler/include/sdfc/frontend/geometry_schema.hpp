#pragma once
// The geometry part of the schema: node kinds, their parameters, modifiers.
#include <string_view>
#include <vector>

#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {

// Names a user may write as a geometry node's kind key, and its modifiers.
const std::vector<std::string_view>& geometry_kinds();
const std::vector<std::string_view>& geometry_modifiers();

class GeometryLowering {
 public:
  GeometryLowering(ValueReader& r, ir::Builder& b, const ir::RenderPlan& plan) : r_(r), b_(b), plan_(plan) {}
  // Returns the node for a geometry map (kNoNode after reporting an error).
  ir::NodeId lower(const SourceValue& v);

 private:
  ir::NodeId lower_kind(const SourceValue& key, const SourceValue& body);
  ir::NodeId lower_children(ir::Kind k, const SourceValue& key, const SourceValue& list, std::vector<Param> params);
  ir::NodeId apply_modifiers(const SourceValue& node, ir::NodeId child);

  ValueReader& r_;
  ir::Builder& b_;
  const ir::RenderPlan& plan_;
};

}  // namespace sdfc::frontend
