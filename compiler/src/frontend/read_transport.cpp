// Reads the path integrator's keys of `render` and of each material.
#include "read_transport.hpp"

#include <cmath>

namespace sdfc::frontend {

void read_transport(ValueReader& r, const SourceValue& render, ir::Transport& t) {
  if (!render.is_map()) return;  // read_render reported it
  if (const SourceValue* v = render.find("integrator"))
    t.integrator = r.word(*v, "render.integrator", {"direct", "path"}) == "path" ? ir::Transport::Integrator::Path
                                                                                 : ir::Transport::Integrator::Direct;
  if (const SourceValue* v = render.find("max_bounces")) t.max_bounces = r.integer(*v, "render.max_bounces", 1, 64);
  if (const SourceValue* v = render.find("firefly_clamp")) t.clamp = r.number(*v, "render.firefly_clamp", Range::non_negative(1e6));
}

void read_material_pbr(ValueReader& r, const SourceValue& body, const std::string& what, ir::MaterialDef& md) {
  if (!body.is_map()) return;  // read_materials reported it
  const SourceValue* rough = body.find("roughness");
  const SourceValue* metal = body.find("metalness");
  md.glossy = rough || metal;
  if (rough) md.roughness = r.number(*rough, what + ".roughness", Range::closed(0, 1));
  if (metal) md.metalness = r.number(*metal, what + ".metalness", Range::closed(0, 1));
  if (const SourceValue* e = body.find("emission")) md.emission = r.vec3(*e, what + ".emission", Range::closed(0, 1e4));
  if (const SourceValue* g = body.find("glass")) read_glass(r, *g, what + ".glass", md, rough ? rough : metal);
}

// glass: {ior, absorption: [r, g, b]} (per unit length) or {ior, color, distance}
// (the colour white light takes after `distance` inside).
void read_glass(ValueReader& r, const SourceValue& v, const std::string& what, ir::MaterialDef& md, const SourceValue* lobe) {
  MapReader m(r, v, what, {"ior", "absorption", "color", "distance"});
  if (!m.ok()) return;
  md.glass = true;
  if (lobe)
    r.sink().error(lobe->loc, what + ": glass is smooth; roughness and metalness do not apply to it",
                   "remove roughness/metalness from this material, or drop its glass");
  md.ior = m.number("ior", md.ior, Range::closed(1, 4));
  const SourceValue* abs = m.get("absorption");
  const SourceValue* col = m.get("color");
  if (abs && col) {
    r.sink().error(col->loc, what + ": give either 'absorption' (per unit length) or 'color' with 'distance', not both", "");
    return;
  }
  if (abs) md.absorption = m.vec3("absorption", md.absorption, Range::non_negative(1e4));
  if (col) {
    ir::Vec3d c = m.vec3("color", {1, 1, 1}, Range::closed(1e-4, 1));
    double d = m.number("distance", 1, Range::positive(1e6));
    for (int i = 0; i < 3; ++i) md.absorption[i] = -std::log(c[i]) / d;
  } else if (const SourceValue* d = m.get("distance")) {
    r.sink().error(d->loc, what + ".distance: the distance at which 'color' is reached; give the color too", "e.g. color: [0.6, 0.8, 1]");
  }
}

}  // namespace sdfc::frontend
