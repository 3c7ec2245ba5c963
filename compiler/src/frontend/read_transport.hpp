#pragma once
// The path integrator's settings: `render.integrator`,
// `render.max_bounces`, `render.firefly_clamp`, and a material's `roughness`,
// `metalness`, `emission` and `glass` (docs/scene-format.md, "Light transport").
// The keys are allowed by the readers of `render` and of a material; these
// functions only read them.
#include "sdfc/frontend/value_reader.hpp"
#include "sdfc/ir/render_plan.hpp"

namespace sdfc::frontend {
void read_transport(ValueReader& r, const SourceValue& render, ir::Transport& t);
// background: {sky: {sun_direction, turbidity, sun_intensity}}; fills
// bg.sky (with its derived colours) and sets top/bottom to the sky's zenith
// and horizon, so the default ambient fill matches it.
void read_sky(ValueReader& r, const SourceValue& v, ir::Background& bg);
// With a sky, its sun as a directional light with hard shadows.
void add_sun(ir::RenderPlan& plan);
void read_material_pbr(ValueReader& r, const SourceValue& body, const std::string& what, ir::MaterialDef& md);
// A material's `glass:` map; `lobe` is its roughness or metalness key, if any
// (smooth glass has neither).
void read_glass(ValueReader& r, const SourceValue& v, const std::string& what, ir::MaterialDef& md, const SourceValue* lobe);
}  // namespace sdfc::frontend

namespace sdfc::frontend {
// background: {map: FILE.exr | FILE.hdr, rotation, intensity, visible,
// sampling} (read_environment.cpp): reads and checks the file, relative to
// the scene file, and builds its sampling tables into bg.map.
// Reports its other keys when there is no map.
void read_environment_map(ValueReader& r, MapReader& m, ir::Background& bg);
}  // namespace sdfc::frontend
