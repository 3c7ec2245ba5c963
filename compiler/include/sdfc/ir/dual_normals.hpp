#pragma once
// render.normals: dual — the kinds whose distance the emitter can
// differentiate exactly (forward mode: each node carries its gradient).
#include "sdfc/ir/node_kind.hpp"

namespace sdfc::ir {

inline bool supports_dual_normals(Kind k) {
  switch (k) {
    case Kind::Sphere:
    case Kind::Box:
    case Kind::Torus:
    case Kind::Plane:
    case Kind::Cylinder:
    case Kind::Capsule:
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
    case Kind::StepFactor: return true;
    default: return false;
  }
}

inline const char* dual_normal_kinds() {
  return "sphere, box, torus, plane, cylinder, capsule and the combinators and modifiers";
}

}  // namespace sdfc::ir
