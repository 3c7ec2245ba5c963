// Reads the path integrator's keys of `render` and of each material.
#include "read_transport.hpp"

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
}

}  // namespace sdfc::frontend
