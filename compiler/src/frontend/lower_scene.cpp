// Schema check and lowering of a scene (see docs/scene-format.md) into the
// SDF IR plus the render plan.
#include "sdfc/frontend/lower_scene.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "sdfc/frontend/geometry_schema.hpp"
#include "sdfc/frontend/value_reader.hpp"

namespace sdfc {

namespace {

using frontend::MapReader;
using frontend::Range;
using frontend::ValueReader;
using frontend::Vec3d;

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void read_camera(ValueReader& r, const SourceValue& v, ir::Camera& cam) {
  MapReader m(r, v, "camera", {"position", "target", "up", "fov"});
  cam.loc = v.loc;
  cam.position = m.vec3("position", cam.position);
  cam.target = m.vec3("target", cam.target);
  cam.up = m.direction("up", cam.up);
  cam.fov_degrees = m.number("fov", cam.fov_degrees, {0, 179, true});
  Vec3d f{cam.target[0] - cam.position[0], cam.target[1] - cam.position[1], cam.target[2] - cam.position[2]};
  double len = std::sqrt(dot(f, f));
  if (len < 1e-9) {
    r.sink().error(v.loc, "camera: target is at the camera position, so there is no view direction", "move the target");
    return;
  }
  double c = std::fabs(dot(f, cam.up)) / len;
  if (c > 0.9999)
    r.sink().error(m.get("up") ? m.get("up")->loc : v.loc, "camera: up is parallel to the view direction",
                   "choose an up vector across the view, e.g. [0, 0, 1] for a camera looking along y");
}

void read_render(ValueReader& r, const SourceValue& v, ir::MarchSettings& s) {
  MapReader m(r, v, "render", {"width", "height", "precision", "max_steps", "hit_epsilon", "max_distance",
                               "step_factor", "gamma", "normals", "lipschitz_correction"});
  s.width = m.integer("width", s.width, 1, 16384);
  s.height = m.integer("height", s.height, 1, 16384);
  s.precision = m.word("precision", "float", {"float", "double"}) == "double" ? ir::Precision::Double : ir::Precision::Float;
  s.max_steps = m.integer("max_steps", s.max_steps, 1, 100000);
  s.hit_epsilon = m.number("hit_epsilon", s.hit_epsilon, {0, 1000, true});
  s.max_distance = m.number("max_distance", s.max_distance, Range::positive());
  s.step_factor = m.number("step_factor", s.step_factor, {0, 2, true});
  s.lipschitz_correction = m.word("lipschitz_correction", "true", {"true", "false"}) == "true";
  s.gamma = m.number("gamma", s.gamma, {0, 10, true});
  s.normals = m.word("normals", "tetrahedral", {"tetrahedral", "central"}) == "central" ? ir::NormalMethod::Central
                                                                                         : ir::NormalMethod::Tetrahedral;
}

void read_background(ValueReader& r, const SourceValue& v, ir::Background& bg) {
  Range unit = Range::closed(0, 1000);
  if (v.is_seq()) {
    bg.top = bg.bottom = r.vec3(v, "background", unit);
    return;
  }
  MapReader m(r, v, "background", {"top", "bottom"});
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
      MapReader m(r, body, what, {"direction", "color", "intensity"});
      l.kind = ir::LightKind::Directional;
      l.direction = m.direction("direction", {0.577, 0.577, -0.577});
      l.color = m.vec3("color", l.color, unit);
      l.intensity = m.number("intensity", 1.0, Range::non_negative(1e4));
    } else if (key.scalar == "point") {
      MapReader m(r, body, what, {"position", "color", "intensity"});
      l.kind = ir::LightKind::Point;
      if (m.require("position")) l.position = m.vec3("position", l.position);
      l.color = m.vec3("color", l.color, unit);
      l.intensity = m.number("intensity", 1.0, Range::non_negative(1e6));
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
    MapReader m(r, body, "material '" + md.name + "'", {"color", "specular", "shininess"});
    md.color = m.vec3("color", md.color, Range::closed(0, 1));
    md.specular = m.number("specular", md.specular, Range::closed(0, 100));
    md.shininess = m.number("shininess", md.shininess, Range::closed(1, 10000));
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

ir::Module lower_scene(const SourceValue& doc, const std::string& source_name) {
  DiagnosticSink sink;
  ValueReader r(sink);
  ir::Module m;
  m.source_name = source_name;
  if (!doc.is_map()) {
    sink.error(doc.loc, "a scene file is a map of sections (camera, render, lights, materials, scene), got " + doc.kind_name(), "");
    sink.throw_if_any();
  }
  MapReader top(r, doc, "the scene file", {"camera", "render", "background", "lights", "materials", "scene"});

  ir::RenderPlan& plan = m.plan;
  plan.materials.push_back({"default", {0.8, 0.8, 0.8}, 0.2, 32, {}});
  if (auto* v = top.get("camera")) read_camera(r, *v, plan.camera);
  if (auto* v = top.get("render")) read_render(r, *v, plan.march);
  if (auto* v = top.get("background")) read_background(r, *v, plan.background);
  if (auto* v = top.get("materials")) read_materials(r, *v, plan);
  if (auto* v = top.get("lights")) {
    read_lights(r, *v, plan);
  } else {
    ir::Light key;
    key.direction = {-0.577, 0.577, -0.577};
    plan.lights.push_back(key);
  }
  add_default_ambient(plan);

  ir::Builder b(*m.graph);
  if (const SourceValue* scene = top.require("scene")) {
    frontend::GeometryLowering g(r, b, plan);
    m.root = g.lower(*scene);
  }
  sink.throw_if_any();
  return m;
}

}  // namespace sdfc
