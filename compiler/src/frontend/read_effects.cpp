// Reads `effects:`; each sub-section present turns its effect on.
#include "read_effects.hpp"

namespace sdfc::frontend {

namespace {

void read_ambient_occlusion(ValueReader& r, const SourceValue& v, ir::AmbientOcclusion& ao) {
  MapReader m(r, v, "effects.ambient_occlusion", {"method", "samples", "distance", "strength"});
  ao.enabled = true;
  ao.method = m.word("method", "normal_samples", {"normal_samples", "step_count"}) == "step_count"
                  ? ir::AmbientOcclusion::Method::StepCount
                  : ir::AmbientOcclusion::Method::NormalSamples;
  ao.samples = m.integer("samples", ao.samples, 1, 64);
  ao.distance = m.number("distance", ao.distance, Range::positive(1e4));
  ao.strength = m.number("strength", ao.strength, Range::closed(0, 100));
}

void read_glow(ValueReader& r, const SourceValue& v, ir::Glow& g) {
  MapReader m(r, v, "effects.glow", {"color", "strength", "radius", "step_strength"});
  g.enabled = true;
  g.color = m.vec3("color", g.color, Range::closed(0, 1000));
  g.strength = m.number("strength", g.strength, Range::non_negative(1e4));
  g.radius = m.number("radius", g.radius, Range::positive(1e4));
  g.step_strength = m.number("step_strength", g.step_strength, Range::non_negative(1e4));
}

void read_fog(ValueReader& r, const SourceValue& v, ir::Fog& f) {
  MapReader m(r, v, "effects.fog", {"color", "density", "height_falloff", "base_height"});
  f.enabled = true;
  f.color = m.vec3("color", f.color, Range::closed(0, 1000));
  Param density = m.param("density", f.density, Range::non_negative(1e3));
  f.density = density.value, f.density_anim = density.anim;
  f.height_falloff = m.number("height_falloff", f.height_falloff, Range::non_negative(1e3));
  f.base_height = m.number("base_height", f.base_height);
}

void read_reflections(ValueReader& r, const SourceValue& v, ir::Reflections& refl) {
  MapReader m(r, v, "effects.reflections", {"depth"});
  refl.depth = m.integer("depth", 1, 0, 8);
}

// `fog: false` (or null) leaves an effect off, so `--set effects.fog=false`
// can switch off one effect of a scene.
const SourceValue* enabled(const MapReader& m, std::string_view key) {
  const SourceValue* x = m.get(key);
  if (x && (x->is_null() || (x->is_scalar() && !x->quoted && x->scalar == "false"))) return nullptr;
  return x;
}

}  // namespace

void read_effects(ValueReader& r, const SourceValue& v, ir::Effects& fx) {
  MapReader m(r, v, "effects", {"ambient_occlusion", "glow", "fog", "reflections"});
  if (auto* x = enabled(m, "ambient_occlusion")) read_ambient_occlusion(r, *x, fx.ambient_occlusion);
  if (auto* x = enabled(m, "glow")) read_glow(r, *x, fx.glow);
  if (auto* x = enabled(m, "fog")) read_fog(r, *x, fx.fog);
  if (auto* x = enabled(m, "reflections")) read_reflections(r, *x, fx.reflections);
}

}  // namespace sdfc::frontend
