#pragma once
// Everything about a render that is not geometry: camera, lights, materials,
// background, marcher settings and effects. Kept apart from the SDF DAG so
// passes over geometry never see it and vice versa.
#include "sdfc/expr/expr.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "sdfc/ir/background.hpp"
#include "sdfc/ir/transport.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::ir {

using Vec3d = std::array<double, 3>;

// A key of a camera path: where the camera is and looks at a given time.
struct CameraKey {
  double time = 0;
  Vec3d position{0, -3, 0};
  Vec3d target{0, 0, 0};
};

struct Camera {
  Vec3d position{0, -3, 0};
  Vec3d target{0, 0, 0};
  Vec3d up{0, 0, 1};
  double fov_degrees = 45;  // along fov_axis
  // Which side of the image the fov spans: vertical, horizontal, or auto
  // (the longer side, as Blender's sensor fit "auto").
  enum class FovAxis { Vertical, Horizontal, Auto } fov_axis = FovAxis::Vertical;
  // camera.fit: the host places the camera so fit_lo..fit_hi (the scene's
  // bounds, recorded by the analyse pass) fill the frame, looking along
  // `direction` (or position -> target when direction is all zero).
  bool fit = false;
  Vec3d direction{0, 0, 0};
  bool has_fit_box = false;
  Vec3d fit_lo{0, 0, 0}, fit_hi{0, 0, 0};
  // Depth of field: lens diameter (0 = pinhole) and the distance in focus
  // (0 = the distance to the target).
  double aperture = 0;
  double focus_distance = 0;
  // A camera path (empty: the camera is static). The host evaluates it per
  // frame into the frame block, so an animation never recompiles.
  std::vector<CameraKey> path;
  enum class Interpolation { Linear, CatmullRom } interpolation = Interpolation::Linear;
  SourceLoc loc;
};

enum class Precision { Float, Double };
enum class NormalMethod { Tetrahedral, Central, Dual };

struct MarchSettings {
  int width = 1280;
  int height = 720;
  Precision precision = Precision::Float;
  int max_steps = 256;
  double hit_epsilon = 0.5;  // in pixels: hit when d < hit_epsilon * t * pixel_angle
  double max_distance = 50;
  double step_factor = 1.0;
  bool lipschitz_correction = true;  // divide subtrees with L > 1 by L
  double gamma = 2.2;
  NormalMethod normals = NormalMethod::Tetrahedral;
  double normal_step = 0.5;  // finite-difference normal step, in pixel footprints at the hit
  // The smallest step in world units. 1e-6 unless render.normal_step is
  // given (then 1e-12): the 1e-6 floor smooths the normals of deep zooms,
  // in double too.
  double normal_step_floor = 1e-6;
  // After a hit, bracket the surface and bisect it (the reference render).
  enum class Refine { None, Bisection } refine = Refine::None;
  // Anti-aliasing: jittered samples per pixel and the reconstruction filter
  // (box: one pixel wide; tent: two pixels wide, importance-sampled).
  int samples = 1;
  enum class Filter { Box, Tent } filter = Filter::Box;
  // Where the samples go: the R2 sequence rotated per pixel, or a square
  // stratified grid of cell centres (samples must then be a square, N x N).
  enum class Sampling { R2, Grid } sampling = Sampling::R2;
  bool dither = false;  // jitter the first march step against banding
  bool alpha = false;   // images carry coverage as alpha and leave the background out
  // Exposure in stops, then the tone curve, then gamma.
  double exposure = 0;
  enum class ToneMapping { Clamp, Reinhard, Aces } tone_mapping = ToneMapping::Clamp;
};

// The reference render (sdfc render --reference): the same view,
// slow but trustworthy: double precision, a small hit epsilon (in pixel
// footprints), 20000 steps of half the distance, every hit bisected.
// With grid > 1 it traces a grid x grid stratified grid of rays per pixel
// (box filter), so its AOVs are pixel averages: coverage, mean normal and
// depth (sdfc render --reference-samples; 1 ray = the pixel centre).
// It answers: which surface does the pixel see, and its normal at
// the pixel's scale - central differences in double with the render's
// default step (0.5 px, no world-unit floor) at the bisected hit, so the
// normal is the one a render resolves, not sub-pixel detail (dual normals
// stay: they are exact already).
inline constexpr double kReferenceHitEpsilon = 0.01;  // px; why: docs/accuracy.md
inline constexpr int kReferenceGrid = 8;  // 8 x 8 rays per pixel; why: docs/accuracy.md
inline void make_reference(MarchSettings& s, double hit_epsilon = kReferenceHitEpsilon, int grid = 1) {
  if (grid > 1) {
    s.samples = grid * grid;
    s.sampling = MarchSettings::Sampling::Grid;
    s.filter = MarchSettings::Filter::Box;
  }
  s.precision = Precision::Double;
  s.hit_epsilon = hit_epsilon;
  s.max_steps = 20000;
  s.step_factor = 0.5;
  s.refine = MarchSettings::Refine::Bisection;
  if (s.normals != NormalMethod::Dual) s.normals = NormalMethod::Central;
  s.normal_step = 0.5;
  s.normal_step_floor = 1e-12;
  s.dither = false;
}

enum class LightKind { Directional, Point, Ambient };

struct Light {
  LightKind kind = LightKind::Directional;
  Vec3d direction{0, 0, -1};  // directional: the way the light travels (unit)
  Vec3d position{0, 0, 0};    // point
  Vec3d color{1, 1, 1};
  double intensity = 1.0;
  // Animated (an expression of time; null when static): the intensity of a
  // directional or point light, the position of a point light. The values
  // above are then those at time 0.
  expr::ExprPtr intensity_anim;
  std::array<expr::ExprPtr, 3> position_anim{};
  // Shadows towards this light: hard (a hit/miss march) or soft (Quilez's
  // penumbra estimate, sharper for larger softness), with their own budget.
  enum class Shadows { None, Hard, Soft } shadows = Shadows::None;
  double softness = 16;
  int shadow_steps = 64;
  SourceLoc loc;
};

// What an orbit point is measured against for the orbit trap (the smallest
// value along the orbit): the nearest coordinate plane (`cross`, the
// default), a point, a plane, a line, or a sphere's shell.
struct TrapShape {
  enum class Kind { Cross, Point, Plane, Line, Sphere } kind = Kind::Cross;
  Vec3d point{0, 0, 0};      // the point; a point on the plane or line; the sphere's centre
  Vec3d direction{0, 0, 1};  // plane: its unit normal; line: its unit direction
  double radius = 1;         // sphere
};

// Past a palette's ends: hold the end colours, start again, or walk back.
enum class PaletteRepeat { Clamp, Repeat, Mirror };

// One source of a material's `coloring:` (several are mixed by weight): a
// value at the hit mapped onto its own palette, as an orbit trap's value is.
struct ColourSource {
  enum class Kind { Trap, Iteration, Normal, Position } kind = Kind::Trap;
  TrapShape shape;        // trap
  Vec3d axis{0, 0, 1};    // normal, position: the value is dot(n, axis) or dot(p, axis)
  std::vector<Vec3d> palette;
  std::vector<double> positions;  // of the palette's colours, ascending in [0, 1]
  bool range_auto = true;         // filled in when the kernel is emitted (codegen/trap_range)
  double lo = 0, hi = 1, offset = 0, cycles = 1;
  PaletteRepeat repeat = PaletteRepeat::Clamp;
  double weight = 1;
};

struct MaterialDef {
  std::string name;
  Vec3d color{0.8, 0.8, 0.8};
  double specular = 0.2;
  double shininess = 32;
  // Orbit-trap colour: at the hit, the fractal's orbit trap picks a
  // colour from the palette, mixed into `color` by trap_mix. Empty: none.
  std::vector<Vec3d> trap_palette;
  double trap_mix = 0.0;
  // What walks the palette: the orbit trap, or the smooth iteration count
  // (`orbit_trap.source: iteration`).
  enum class TrapSource { Trap, Iteration } trap_source = TrapSource::Trap;
  // The trap's shape (`orbit_trap.shape`); the default keeps today's kernel.
  TrapShape trap_shape;
  // Where each palette colour sits along the palette, ascending in [0, 1]
  // (evenly spaced for `palette:`, as written for `gradient:`).
  std::vector<double> trap_positions;
  // The value range that spans the palette once: `range: [lo, hi]`, or
  // (trap_range_auto, the default) the range the value takes over the
  // fractal's surface, found when the kernel is emitted (codegen/trap_range).
  bool trap_range_auto = true;
  double trap_lo = 0, trap_hi = 1;
  // palette position = (value - lo) / (hi - lo) * cycles + offset, then
  // clamped, wrapped (repeat) or reflected (mirror) into [0, 1].
  double trap_offset = 0, trap_cycles = 1;
  using TrapRepeat = PaletteRepeat;
  TrapRepeat trap_repeat = TrapRepeat::Clamp;
  // `coloring:` several sources, each through its palette, mixed by weight
  // and then into `color` by coloring_mix. Empty: none. Its trap or
  // iteration source (one at most) sets trap_source and trap_shape.
  std::vector<ColourSource> coloring;
  double coloring_mix = 1;
  // The colour reads the fractal's orbit: an orbit_trap, or a coloring with
  // a trap or iteration source.
  bool orbit_coloured() const {
    for (const auto& s : coloring)
      if (s.kind == ColourSource::Kind::Trap || s.kind == ColourSource::Kind::Iteration) return true;
    return !trap_palette.empty();
  }
  // A coloring source reads the hit's normal or position.
  bool geometry_coloured() const {
    for (const auto& s : coloring)
      if (s.kind == ColourSource::Kind::Normal || s.kind == ColourSource::Kind::Position) return true;
    return false;
  }
  double reflectivity = 0;  // reflectance at normal incidence (Fresnel-Schlick R0)
  // The path integrator's surface: a GGX lobe when `glossy`
  // (roughness or metalness given), light emitted by the surface.
  bool glossy = false;
  double roughness = 0.5, metalness = 0;
  Vec3d emission{0, 0, 0};
  // A smooth dielectric (`glass:`, path integrator only): Fresnel
  // reflection and refraction with index `ior`, light inside dimmed by
  // exp(-absorption * distance) per channel (Beer-Lambert).
  bool glass = false;
  double ior = 1.5;
  Vec3d absorption{0, 0, 0};
  SourceLoc loc;
};

// Effects: each is emitted into the kernel only when enabled here.
struct AmbientOcclusion {
  bool enabled = false;
  enum class Method { NormalSamples, StepCount } method = Method::NormalSamples;
  int samples = 5;        // normal_samples: distance probes along the normal
  double distance = 0.5;  // normal_samples: how far the probes reach
  double strength = 1.0;
};

struct Glow {
  bool enabled = false;
  Vec3d color{1.0, 0.8, 0.5};
  double strength = 1.0;       // from the closest approach of a missed ray
  double radius = 0.1;         // closest approach at which that glow fades out
  double step_strength = 0.0;  // from the march's step count (steps / max_steps)
};

struct Fog {
  bool enabled = false;
  Vec3d color{0.5, 0.6, 0.7};
  double density = 0.05;        // extinction per unit distance at base_height
  expr::ExprPtr density_anim;   // animated density (null when static)
  double height_falloff = 0.0;  // > 0: density falls as exp(-falloff * (height - base_height))
  double base_height = 0.0;     // height along the camera's up vector
};

struct Reflections {
  int depth = 0;  // bounces after the primary hit; 0 = off
};

struct Effects {
  AmbientOcclusion ambient_occlusion;
  Glow glow;
  Fog fog;
  Reflections reflections;
};

struct RenderPlan {
  Camera camera;
  MarchSettings march;
  Background background;
  std::vector<Light> lights;
  // Material id i is materials[i]; id 0 is the default material.
  std::vector<MaterialDef> materials;
  Effects effects;
  Transport transport;
};

}  // namespace sdfc::ir
