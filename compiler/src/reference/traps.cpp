// Reference (double, CPU) orbit colour of the fractal kinds: the orbit trap
// (the smallest measure of the orbit against the trap's shape: by default
// its smallest |coordinate|) and the smooth iteration count, written from
// the formulas in each fractal's description (compiler/src/kinds/),
// independently of stdlib/fractal_traps.cl.
#include "sdfc/kinds/registry.hpp"
#include "sdfc/reference/evaluator.hpp"

namespace sdfc::reference {

std::optional<OrbitColour> orbit_colour(const ir::Node& n, const Vec3& p, const ir::TrapShape& shape) {
  const kinds::Description* d = kinds::find(n.kind);
  if (!d || !d->orbit_colour) return std::nullopt;
  return d->orbit_colour(n, p, shape);
}

}  // namespace sdfc::reference
