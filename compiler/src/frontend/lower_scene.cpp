// Schema check and lowering of a scene (see docs/scene-format.md) into the
// SDF IR plus the render plan.
#include "sdfc/frontend/lower_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "sdfc/frontend/geometry_schema.hpp"
#include "sdfc/ir/dual_normals.hpp"
#include "sdfc/frontend/value_reader.hpp"
#include "too_small.hpp"
#include "scene_name.hpp"
#include "read_camera.hpp"
#include "sdfc/frontend/bookmarks.hpp"
#include "read_effects.hpp"
#include "read_orbit_trap.hpp"
#include "read_transport.hpp"

namespace sdfc {

namespace {

using frontend::MapReader;
using frontend::Range;
using frontend::ValueReader;
using frontend::Vec3d;
using frontend::too_small;
using frontend::scene_name;

void read_render(ValueReader& r, const SourceValue& v, ir::MarchSettings& s) {
  MapReader m(r, v, "render", {"width", "height", "precision", "max_steps", "hit_epsilon", "max_distance",
                               "step_factor", "gamma", "normals", "lipschitz_correction", "samples", "filter",
                               "sampling", "dither", "exposure", "tone_mapping", "normal_step", "refine", "alpha",
                               "integrator", "max_bounces", "firefly_clamp"});  // the last three: read_transport.cpp
  s.width = m.integer("width", s.width, 1, 16384);
  s.height = m.integer("height", s.height, 1, 16384);
  s.precision = m.word("precision", "float", {"float", "double"}) == "double" ? ir::Precision::Double : ir::Precision::Float;
  s.max_steps = m.integer("max_steps", s.max_steps, 1, 100000);
  s.hit_epsilon = m.number("hit_epsilon", s.hit_epsilon, {0, 1000, true});
  s.max_distance = m.number("max_distance", s.max_distance, Range::positive());
  s.step_factor = m.number("step_factor", s.step_factor, {0, 2, true});
  s.lipschitz_correction = m.word("lipschitz_correction", "true", {"true", "false"}) == "true";
  s.gamma = m.number("gamma", s.gamma, {0, 10, true});
  if (s.gamma > 0 && s.gamma < 0.05) too_small(r, *m.get("gamma"), "render.gamma", s.gamma, 0.05);  // 1/gamma is a literal
  std::string normals = m.word("normals", "tetrahedral", {"tetrahedral", "central", "dual"});
  s.normals = normals == "central" ? ir::NormalMethod::Central
              : normals == "dual"  ? ir::NormalMethod::Dual
                                   : ir::NormalMethod::Tetrahedral;
  if (v.find("normal_step")) s.normal_step_floor = 1e-12;  // a chosen step is taken as it is
  s.normal_step = m.number("normal_step", s.normal_step, {0, 100, true});
  if (s.normal_step > 0 && s.normal_step < 1e-6)  // the normal would be zero
    too_small(r, *m.get("normal_step"), "render.normal_step", s.normal_step, 1e-6);
  s.refine = m.word("refine", "none", {"none", "bisection"}) == "bisection" ? ir::MarchSettings::Refine::Bisection
                                                                             : ir::MarchSettings::Refine::None;
  s.samples = m.integer("samples", s.samples, 1, 1024);
  s.filter = m.word("filter", "box", {"box", "tent"}) == "tent" ? ir::MarchSettings::Filter::Tent
                                                                 : ir::MarchSettings::Filter::Box;
  if (m.word("sampling", "r2", {"r2", "grid"}) == "grid") {
    s.sampling = ir::MarchSettings::Sampling::Grid;
    const int n = static_cast<int>(std::floor(std::sqrt(double(s.samples))));
    if (n * n != s.samples) {
      const SourceValue* at = v.find("samples");
      r.sink().error(at ? at->loc : v.loc,
                     fmt::format("render.sampling: grid needs render.samples to be a square (N x N), got {}", s.samples),
                     fmt::format("use samples: {} or {}", n * n, (n + 1) * (n + 1)));
    }
  }
  s.dither = m.word("dither", "false", {"false", "true"}) == "true";
  s.alpha = m.word("alpha", "false", {"false", "true"}) == "true";
  s.exposure = m.number("exposure", s.exposure, Range::closed(-20, 20));
  std::string tm = m.word("tone_mapping", "clamp", {"clamp", "reinhard", "aces"});
  s.tone_mapping = tm == "aces"       ? ir::MarchSettings::ToneMapping::Aces
                   : tm == "reinhard" ? ir::MarchSettings::ToneMapping::Reinhard
                                      : ir::MarchSettings::ToneMapping::Clamp;
}

// Per-light shadow settings, shared by directional and point lights.
void read_shadows(MapReader& m, ir::Light& l) {
  std::string sh = m.word("shadows", "none", {"none", "hard", "soft"});
  l.shadows = sh == "soft" ? ir::Light::Shadows::Soft : sh == "hard" ? ir::Light::Shadows::Hard : ir::Light::Shadows::None;
  l.softness = m.number("softness", l.softness, Range::positive(1e4));
  l.shadow_steps = m.integer("shadow_steps", l.shadow_steps, 1, 10000);
}

void read_background(ValueReader& r, const SourceValue& v, ir::Background& bg) {
  Range unit = Range::closed(0, 1000);
  if (v.is_seq()) {
    bg.top = bg.bottom = r.vec3(v, "background", unit);
    return;
  }
  MapReader m(r, v, "background", {"top", "bottom", "sky", "map", "rotation", "intensity", "visible", "sampling"});
  frontend::read_environment_map(r, m, bg);  // read_environment.cpp
  if (const SourceValue* sky = m.get("sky")) return frontend::read_sky(r, *sky, bg);  // read_transport.cpp
  bg.top = m.vec3("top", bg.top, unit);
  bg.bottom = m.vec3("bottom", bg.bottom, unit);
}

void read_lights(ValueReader& r, const SourceValue& v, ir::RenderPlan& plan) {
  if (!v.is_seq()) {
    r.sink().error(v.loc, "lights: expected a list of lights, e.g. '- directional: {direction: [0, 0, -1]}'", "");
    return;
  }
  Range unit = Range::closed(0, 1000);
  for (const auto& item : v.items) {
    if (!item.is_map() || item.entries.size() != 1) {
      r.sink().error(item.loc, "a light is a map with one key: directional, point or ambient", "");
      continue;
    }
    const auto& [key, body] = item.entries.front();
    ir::Light l;
    l.loc = key.loc;
    std::string what = "light '" + key.scalar + "'";
    if (key.scalar == "directional") {
      MapReader m(r, body, what, {"direction", "color", "intensity", "shadows", "softness", "shadow_steps"});
      l.kind = ir::LightKind::Directional;
      l.direction = m.direction("direction", {0.577, 0.577, -0.577});
      l.color = m.vec3("color", l.color, unit);
      frontend::Param intensity = m.param("intensity", 1.0, Range::non_negative(1e4));
      l.intensity = intensity.value, l.intensity_anim = intensity.anim;
      read_shadows(m, l);
    } else if (key.scalar == "point") {
      MapReader m(r, body, what, {"position", "color", "intensity", "shadows", "softness", "shadow_steps"});
      l.kind = ir::LightKind::Point;
      if (m.require("position")) {
        frontend::Param3 p = m.param3("position", l.position);
        for (int i = 0; i < 3; ++i) l.position[i] = p[i].value, l.position_anim[i] = p[i].anim;
      }
      l.color = m.vec3("color", l.color, unit);
      frontend::Param intensity = m.param("intensity", 1.0, Range::non_negative(1e6));
      l.intensity = intensity.value, l.intensity_anim = intensity.anim;
      read_shadows(m, l);
    } else if (key.scalar == "ambient") {
      MapReader m(r, body, what, {"color", "intensity"});
      l.kind = ir::LightKind::Ambient;
      l.color = m.vec3("color", l.color, unit);
      l.intensity = m.number("intensity", 0.1, Range::non_negative(100));
    } else {
      r.sink().error(key.loc, fmt::format("unknown light kind '{}'", key.scalar),
                     did_you_mean(key.scalar, {"directional", "point", "ambient"}));
      continue;
    }
    plan.lights.push_back(l);
  }
}

void read_materials(ValueReader& r, const SourceValue& v, ir::RenderPlan& plan) {
  if (!v.is_map()) {
    r.sink().error(v.loc, "materials: expected a map from names to materials, e.g. 'bone: {color: [0.9, 0.85, 0.75]}'", "");
    return;
  }
  for (const auto& [key, body] : v.entries) {
    ir::MaterialDef md;
    md.name = key.scalar;
    md.loc = key.loc;
    if (md.name == "default") {
      r.sink().error(key.loc, "'default' is the built-in material's name", "choose another name");
      continue;
    }
    MapReader m(r, body, "material '" + md.name + "'", {"color", "specular", "shininess", "orbit_trap", "coloring", "reflectivity",
                                                            "roughness", "metalness", "emission", "glass"});
    md.color = m.vec3("color", md.color, Range::closed(0, 1));
    md.specular = m.number("specular", md.specular, Range::closed(0, 100));
    md.shininess = m.number("shininess", md.shininess, Range::closed(1, 10000));
    md.reflectivity = m.number("reflectivity", md.reflectivity, Range::closed(0, 1));
    if (const SourceValue* t = m.get("orbit_trap")) frontend::read_orbit_trap(r, *t, md);
    if (const SourceValue* c = m.get("coloring")) {
      if (m.get("orbit_trap"))
        r.sink().error(c->loc, "material '" + md.name + "': give either 'orbit_trap' (one source) or 'coloring' (several mixed), not both",
                       "an orbit_trap is a coloring with one trap source");
      else frontend::read_coloring(r, *c, md);
    }
    frontend::read_material_pbr(r, body, "material '" + md.name + "'", md);
    plan.materials.push_back(md);
  }
}

// With no ambient light listed, a dim fill from the background's average
// colour keeps unlit sides from going pure black (Fragmentarium does the same).
void add_default_ambient(ir::RenderPlan& plan) {
  for (const auto& l : plan.lights)
    if (l.kind == ir::LightKind::Ambient) return;
  ir::Light a;
  a.kind = ir::LightKind::Ambient;
  for (int i = 0; i < 3; ++i) a.color[i] = 0.5 * (plan.background.top[i] + plan.background.bottom[i]);
  a.intensity = 0.35;
  plan.lights.push_back(a);
}

}  // namespace

// render.normals: dual needs every node to carry an exact gradient; name the
// first that cannot, at the `normals` setting.
void check_dual_normals(ValueReader& r, const MapReader& top, const ir::Graph& g, ir::NodeId root) {
  for (ir::NodeId id : g.postorder(root)) {
    const ir::Node& n = g.node(id);
    const SourceValue* at = top.get("render")->find("normals");
    if (n.animated()) {
      r.sink().error(at->loc,
                     fmt::format("render.normals: dual does not differentiate animated values ('{}', line {})",
                                 scene_name(n), n.loc.line),
                     "use 'normals: tetrahedral' or 'normals: central' for an animated scene");
      return;
    }
    const kinds::Description* d = kinds::find(n.kind);
    const std::string blocked = d && d->dual_normals && d->dual_blocker ? d->dual_blocker(n) : "";
    if (!blocked.empty()) {
      r.sink().error(at->loc,
                     fmt::format("render.normals: dual cannot differentiate '{}' (line {}): {}", scene_name(n), n.loc.line,
                                 blocked),
                     "use 'normals: tetrahedral' or 'normals: central' for this scene");
      return;
    }
    if (ir::supports_dual_normals(n.kind)) continue;
    r.sink().error(at->loc,
                   fmt::format("render.normals: dual needs dual-number derivatives, which '{}' (line {}) does not have; "
                               "they exist for {}",
                               scene_name(n), n.loc.line, ir::dual_normal_kinds()),
                   "use 'normals: tetrahedral' or 'normals: central' for this scene");
    return;
  }
}

ir::Module lower_scene(const SourceValue& doc, const std::string& source_name) {
  DiagnosticSink sink;
  ValueReader r(sink);
  ir::Module m;
  m.source_name = source_name;
  if (!doc.is_map()) {
    sink.error(doc.loc, "a scene file is a map of sections (camera, render, lights, materials, scene), got " + doc.kind_name(), "");
    sink.throw_if_any();
  }
  MapReader top(r, doc, "the scene file", {"camera", "render", "background", "lights", "materials", "effects", "scene",
                                                  "bookmarks"});

  ir::RenderPlan& plan = m.plan;
  ir::MaterialDef builtin;  // the default material: the MaterialDef defaults
  builtin.name = "default";
  plan.materials.push_back(builtin);
  if (auto* v = top.get("camera")) frontend::read_camera(r, *v, plan.camera);
  if (auto* v = top.get("render")) read_render(r, *v, plan.march), frontend::read_transport(r, *v, plan.transport);
  if (auto* v = top.get("background")) read_background(r, *v, plan.background);
  if (auto* v = top.get("materials")) read_materials(r, *v, plan);
  if (auto* v = top.get("effects")) frontend::read_effects(r, *v, plan.effects);
  std::vector<frontend::Bookmark> bookmarks;  // the viewer's; checked here, read there (bookmarks_of)
  if (auto* v = top.get("bookmarks")) frontend::read_bookmarks(r, *v, bookmarks);
  if (auto* v = top.get("lights")) {
    read_lights(r, *v, plan);
  } else if (!plan.background.sky.enabled) {  // a sky brings its sun instead
    ir::Light key;
    key.direction = {-0.577, 0.577, -0.577};
    plan.lights.push_back(key);
  }
  frontend::add_sun(plan);  // background.sky: the sun is a light
  add_default_ambient(plan);

  ir::Builder b(*m.graph);
  if (const SourceValue* scene = top.require("scene")) {
    frontend::GeometryLowering g(r, b, plan);
    m.root = g.lower(*scene);
    if (m.root != ir::kNoNode && plan.march.normals == ir::NormalMethod::Dual) check_dual_normals(r, top, *m.graph, m.root);
  }
  sink.throw_if_any();
  return m;
}

}  // namespace sdfc
