#pragma once
// render.normals: dual — the kinds whose distance the emitter can
// differentiate exactly (forward mode: each node carries its gradient).
#include "sdfc/ir/node_kind.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::ir {

inline bool supports_dual_normals(Kind k) {
  if (const kinds::Description* d = kinds::find(k)) return d->dual_normals;
  switch (k) {
    case Kind::Translate:
    case Kind::Rotate:
    case Kind::Scale:
    case Kind::Union:
    case Kind::Intersection:
    case Kind::Difference:
    case Kind::SmoothUnion:
    case Kind::SmoothIntersection:
    case Kind::SmoothDifference:
    case Kind::Material:
    case Kind::StepFactor:
    case Kind::Bounded: return true;
    default: return false;
  }
}

inline const char* dual_normal_kinds() {
  return "sphere, box, torus, plane, cylinder, capsule, mandelbulb (and its julia form), mandelbox, julia and the "
         "combinators and modifiers";
}

}  // namespace sdfc::ir
