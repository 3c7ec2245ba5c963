#pragma once
// Everything about a render that is not geometry: camera, lights, materials,
// background, marcher settings and effects. Kept apart from the SDF DAG so
// passes over geometry never see it and vice versa.
#include <array>
#include <string>
#include <vector>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::ir {

using Vec3d = std::array<double, 3>;

struct Camera {
  Vec3d position{0, -3, 0};
  Vec3d target{0, 0, 0};
  Vec3d up{0, 0, 1};
  double fov_degrees = 45;  // vertical
  SourceLoc loc;
};

enum class Precision { Float, Double };
enum class NormalMethod { Tetrahedral, Central };

struct MarchSettings {
  int width = 1280;
  int height = 720;
  Precision precision = Precision::Float;
  int max_steps = 256;
  double hit_epsilon = 0.5;  // in pixels: hit when d < hit_epsilon * t * pixel_angle
  double max_distance = 50;
  double step_factor = 1.0;
  bool lipschitz_correction = true;  // divide subtrees with L > 1 by L (issue 9)
  double gamma = 2.2;
  NormalMethod normals = NormalMethod::Tetrahedral;
};

struct Background {
  Vec3d top{0.45, 0.55, 0.7};
  Vec3d bottom{0.15, 0.17, 0.22};
};

enum class LightKind { Directional, Point, Ambient };

struct Light {
  LightKind kind = LightKind::Directional;
  Vec3d direction{0, 0, -1};  // directional: the way the light travels (unit)
  Vec3d position{0, 0, 0};    // point
  Vec3d color{1, 1, 1};
  double intensity = 1.0;
  SourceLoc loc;
};

struct MaterialDef {
  std::string name;
  Vec3d color{0.8, 0.8, 0.8};
  double specular = 0.2;
  double shininess = 32;
  SourceLoc loc;
};

// Effects live in their own struct so the effects work has a place to grow;
// the foundation renders none of them and so emits no code for them.
struct Effects {};

struct RenderPlan {
  Camera camera;
  MarchSettings march;
  Background background;
  std::vector<Light> lights;
  // Material id i is materials[i]; id 0 is the default material.
  std::vector<MaterialDef> materials;
  Effects effects;
};

}  // namespace sdfc::ir
