#pragma once
// Facts about a whole module that the emitters need, recorded once by the
// `analyse` pass (passes/analyse.cpp) so no emitter derives them again.
#include <optional>
#include <vector>

#include "sdfc/ir/graph.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::ir {

// Where rays can meet the scene: its padded bounding box and, when the
// compiler knows one (a lone Mandelbulb or Juliabulb), a tighter ball.
struct RayBounds {
  Box3 box;
  bool has_sphere = false;
  Vec3d center{0, 0, 0};
  double radius = 0;
};

// An unbounded scene that is a plain union of bounded parts and planes (a
// fractal on a floor): the parts' padded box and the planes' outward normals.
// Outside the box the distance to the parts is at least the distance to the
// box, and a ray rising from a plane only moves away from it, so shadow rays
// need not march on to the light once both say nothing can block them or
// darken their penumbra any more (shadow_soft_open, shading_emitter.cpp).
struct ShadowBounds {
  Box3 box;
  std::vector<Vec3d> plane_normals;
};

struct Analyses {
  bool known = false;           // the analyse pass has run
  bool uses_time = false;       // animated geometry, lights or fog: the kernel reads the frame time
  bool material_blend = false;  // a smooth blend joins children that show different materials
  bool orbit_traps = false;     // some material colours by an orbit trap
  bool coloring_geometry = false;  // some material's coloring reads the hit's normal or position
  // The material id of every hit when the whole scene carries one material.
  std::optional<double> uniform_material;
  // Where primary and shadow rays march; none for an unbounded scene.
  std::optional<RayBounds> ray_bounds;
  // For an unbounded scene of bounded parts and planes; see ShadowBounds.
  std::optional<ShadowBounds> shadow_bounds;
};

}  // namespace sdfc::ir
