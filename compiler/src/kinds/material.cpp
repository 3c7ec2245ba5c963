// material: assigns a material (by id in the render plan) to the parts of
// its child that have none; the material nearest the geometry wins.
#include "domain_op.hpp"
#include "../reference/materials.hpp"
#include "sdfc/kinds/folding.hpp"
#include "sdfc/kinds/params.hpp"

SDFC_KIND(Material,           16, "material",            Material,   1, "id",                            "")

namespace sdfc::kinds {
namespace {
using namespace domain;

struct MaterialP {
  double id;
};

ir::Props props(const ir::Graph&, const ir::Node&, const Kid& kid) {
  ir::Props p = kid(0);
  p.cost += 1;
  return p;
}

Sample evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  Sample s = child_at(g, n, p);
  reference::detail::claim(s, int(view<MaterialP>(n).id));
  return s;
}

Carried walk(Walker& w, const ir::Node& n, const std::string& p) {
  const double id = view<MaterialP>(n).id;
  if (w.carries_records()) {  // top-down: the material nearest the geometry is set last
    double outer = w.enter_material(id);
    Carried c = w.child(n.children[0], p);
    w.enter_material(outer);
    return c;
  }
  Carried c = w.child(n.children[0], p);
  if (!w.tracks_material() || w.tracks_trap()) return c;
  std::string lit = w.lit().typed(id);
  // Only unassigned (0) parts take this one.
  if (c.mat == w.lit().typed(0)) return {c.d, lit};
  std::string m = w.var("m");
  w.line(fmt::format("real {} = SEL({}, {}, {} != 0.0f);  // {}", m, lit, c.mat, c.mat, w.describe(n)));
  return {c.d, m};
}

// The material nearest the geometry wins, so an outer one is dead.
ir::NodeId fold(const Folding& f) { return f.child(0).kind == ir::Kind::Material ? f.kids[0] : ir::kNoNode; }

Dual dual(DualWalker& w, const ir::Node& n, const std::string& p) { return w.child(n.children[0], p); }

}  // namespace

int material_id(const ir::Node& material) { return int(view<MaterialP>(material).id); }

namespace described {
extern const Description Material{.kind = ir::Kind::Material,
                                  .yaml = "material",
                                  .param_count = count_of<MaterialP>(),
                                  .dual_normals = true,
                                  .child_props = props,
                                  .evaluate = evaluate,
                                  .walk = walk,
                                  .walk_dual = dual,
                                  .fold = fold,
                                  .fit_children = true};
}

}  // namespace sdfc::kinds
