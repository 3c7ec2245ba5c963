#pragma once
// How light travels in a render: the direct integrator (one
// shading of the first hit, the effects, mirror reflections), or a
// unidirectional path tracer over the distance field. Kept apart from the
// march settings: only the path integrator reads the rest.
namespace sdfc::ir {

struct Transport {
  enum class Integrator { Direct, Path } integrator = Integrator::Direct;
  // The most times a path scatters; light reaching the eye after more
  // scattering events is left out.
  int max_bounces = 4;
  // Russian roulette starts after this many bounces (the paths before it
  // are never cut, so small max_bounces stay deterministic in length).
  int roulette_after = 3;
  // Firefly clamp: each light contribution along a path is limited to this
  // value per channel (0 = no clamp; a clamp darkens, it is a bias).
  double clamp = 0;
};

}  // namespace sdfc::ir
