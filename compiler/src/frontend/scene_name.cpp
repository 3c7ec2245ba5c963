#include "scene_name.hpp"

#include "sdfc/ir/node_kind.hpp"
#include "sdfc/kinds/params.hpp"

namespace sdfc::frontend {

std::string scene_name(const ir::Node& n) {
  std::string name(ir::info(n.kind).name);
  if (n.kind == ir::Kind::ScaleXYZ) return "scale: [x, y, z]";
  if (n.kind != ir::Kind::BlendUnion && n.kind != ir::Kind::BlendIntersection && n.kind != ir::Kind::BlendDifference)
    return name;
  static const char* const kStyles[] = {"smooth_", "smooth_", "chamfer_", "round_", "columns_", "stairs_"};
  const int style = kinds::blend_style(n);
  std::string op = name.substr(6);  // after "blend_"
  if (style < 0 || style > 5) return name;
  if (style < 2) return "smooth_" + op + " (kind: " + (style == 0 ? "cubic" : "exponential") + ")";
  return kStyles[style] + op;
}

}  // namespace sdfc::frontend
