#pragma once
// render.normals: dual — the kinds whose distance the emitter can
// differentiate exactly (forward mode: each node carries its gradient).
#include "sdfc/ir/node_kind.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::ir {

inline bool supports_dual_normals(Kind k) {
  if (const kinds::Description* d = kinds::find(k)) return d->dual_normals;
  if (const kinds::Description* d = kinds::operation(k)) return d->dual_normals;
  return false;
}

inline const char* dual_normal_kinds() {
  return "sphere, box, torus, plane, cylinder, capsule, mandelbulb (and its julia form), mandelbox, julia, "
         "formulas whose estimate uses the scalar derivative, and the combinators and modifiers";
}

}  // namespace sdfc::ir
