#pragma once
// Scenes built from the kind table (compiler/src/kinds/): every described
// kind's example with a material of its own. The bounded examples share one
// scene, each in its own cell of a grid (one kernel per evaluator however
// many kinds there are); an unbounded or large example (a plane, a fractal)
// and every kind that is not a primitive gets a scene alone.
#include <string>
#include <vector>

#include "sdfc/kinds/registry.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::conformance {

struct KindCell {
  const kinds::Description* kind;
  test::V3 centre;    // where the example sits in the scene
  test::V3 lo, hi;    // the example's own bounds (finite ones), around the centre
  std::string material() const { return "k_" + std::string(kind->yaml); }
};

struct KindScene {
  std::string name;
  std::string yaml;
  std::vector<KindCell> cells;
};

// A primitive whose example is bounded and small shares the grid; the
// others (a plane, a large fractal) get a scene each.
bool fits_a_cell(const kinds::Description& d, const ir::Box3& example_bounds);

// These small bounded primitives' examples in one scene, on a grid.
KindScene grid_scene(const std::string& name, const std::vector<const kinds::Description*>& kinds);

// Every described kind is in exactly one of these.
const std::vector<KindScene>& kind_scenes();

// The example alone as a scene, compiled.
ir::Module compile_example(const kinds::Description& d, const std::vector<std::string>& overrides = {});

}  // namespace sdfc::conformance
