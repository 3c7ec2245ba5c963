#include "kind_scenes.hpp"

#include <fmt/format.h>

namespace sdfc::conformance {

using test::add;
using test::V3;

ir::Module compile_example(const kinds::Description& d, const std::vector<std::string>& overrides) {
  return test::compile_text(fmt::format("scene: {}\n", d.example), std::string(d.yaml) + ".yaml", overrides);
}

namespace {

// A colour per kind, so a wrong material is a wrong picture too.
std::string materials_of(const std::vector<KindCell>& cells) {
  std::string out = "materials:\n";
  for (size_t i = 0; i < cells.size(); ++i)
    out += fmt::format("  {}: {{color: [{:.2f}, 0.5, {:.2f}]}}\n", cells[i].material(), 0.2 + 0.6 * double(i % 5) / 4,
                       0.2 + 0.6 * double(i / 5 % 5) / 4);
  return out;
}

// The grid's examples fit in a cube of side 3 about the origin.
constexpr double kSpacing = 4;

}  // namespace

bool fits_a_cell(const kinds::Description& d, const ir::Box3& b) {
  if (ir::info(d.kind).category != ir::Category::Primitive || !b.finite()) return false;
  for (int i = 0; i < 3; ++i)
    if (b.lo[i] < -1.5 || b.hi[i] > 1.5) return false;
  return true;
}

KindScene grid_scene(const std::string& name, const std::vector<const kinds::Description*>& kinds) {
  KindScene grid{name, "", {}};
  for (const kinds::Description* d : kinds) {
    ir::Module m = compile_example(*d);
    const ir::Box3& b = m.graph->node(m.root).props.bounds;
    if (!fits_a_cell(*d, b)) throw std::logic_error(fmt::format("{}: its example does not fit a grid cell", d->yaml));
    size_t n = grid.cells.size();
    V3 centre = {kSpacing * double(n % 5), kSpacing * double(n / 5), 0};
    KindCell cell{d, centre, add(b.lo, centre), add(b.hi, centre)};
    grid.cells.push_back(cell);
  }
  grid.yaml = materials_of(grid.cells) + "scene:\n  union:\n";
  for (const KindCell& c : grid.cells)
    grid.yaml += fmt::format("    - {{union: [{}], material: {}, translate: [{}, {}, {}]}}\n", c.kind->example,
                             c.material(), c.centre[0], c.centre[1], c.centre[2]);
  return grid;
}

namespace {

std::vector<KindScene> build() {
  std::vector<KindScene> scenes;
  std::vector<const kinds::Description*> bounded;
  for (const kinds::Description* d : kinds::all()) {
    ir::Module m = compile_example(*d);
    const ir::Box3& b = m.graph->node(m.root).props.bounds;
    if (fits_a_cell(*d, b)) {
      bounded.push_back(d);
      continue;
    }
    // Alone: in its bounds when they are finite, else about the origin.
    KindCell cell{d, {0, 0, 0}, {-2, -2, -2}, {2, 2, 2}};
    if (b.finite()) cell.lo = b.lo, cell.hi = b.hi;
    std::string yaml = materials_of({cell}) + fmt::format("scene: {{material: {}, {}\n", cell.material(),
                                                          std::string(d->example).substr(1));
    scenes.push_back({"alone_" + std::string(ir::info(d->kind).name), yaml, {cell}});
  }
  if (!bounded.empty()) scenes.insert(scenes.begin(), grid_scene("bounded_kinds", bounded));
  return scenes;
}

}  // namespace

const std::vector<KindScene>& kind_scenes() {
  static const std::vector<KindScene> scenes = build();
  return scenes;
}

}  // namespace sdfc::conformance
