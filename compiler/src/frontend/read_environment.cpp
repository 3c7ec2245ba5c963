// background.map: an equirectangular environment map that lights a path
// traced scene. The file is read here, so `sdfc check` reports a missing or
// broken one at its key; only its pixels go on to the kernel, as a buffer.
#include <filesystem>

#include "env_map_file.hpp"
#include "read_transport.hpp"

namespace sdfc::frontend {

namespace {
// A relative name is relative to the scene file's folder (or the current
// one for a value given with --set).
std::string resolve(const std::string& name, const SourceLoc& at) {
  namespace fs = std::filesystem;
  fs::path p(name);
  if (p.is_absolute() || !at.file) return p.string();
  fs::path scene(*at.file);
  std::error_code ec;
  if (!fs::is_regular_file(scene, ec)) return p.string();
  return (scene.parent_path() / p).string();
}
}  // namespace

void read_environment_map(ValueReader& r, MapReader& m, ir::Background& bg) {
  const SourceValue* at = m.get("map");
  if (!at) {
    for (const char* key : {"rotation", "intensity", "visible", "sampling"})
      if (const SourceValue* v = m.get(key))
        r.sink().error(v->loc, std::string("background.") + key + " applies to an environment map, and there is none",
                       "add map: FILE.exr (or .hdr) to the background, or remove " + std::string(key));
    return;
  }
  if (const SourceValue* sky = m.get("sky")) {
    r.sink().error(sky->loc, "background: give either 'sky' or 'map', not both", "");
    return;
  }
  const SourceValue& file = *at;
  ir::EnvironmentMap& env = bg.map;
  env.rotation = m.number("rotation", env.rotation, Range::closed(-360, 360));
  env.intensity = m.number("intensity", env.intensity, Range::non_negative(1e4));
  env.visible = m.word("visible", "true", {"true", "false"}) == "true";
  env.importance = m.word("sampling", "importance", {"importance", "uniform"}) == "importance";
  if (!file.is_scalar() || file.scalar.empty()) {
    r.sink().error(file.loc, "background.map: expected the name of an equirectangular .exr or .hdr file, got " + file.kind_name(),
                   "e.g. map: studio.hdr");
    return;
  }
  try {
    EnvPixels px = read_env_pixels(resolve(file.scalar, file.loc));
    env.enabled = true;
    env.file = file.scalar;
    env.width = px.width;
    env.height = px.height;
    env.data = std::make_shared<const std::vector<float>>(env_tables(px, env.intensity, env.importance));
  } catch (const EnvMapError& e) {
    r.sink().error(file.loc, "background.map '" + file.scalar + "': " + e.what(), "");
  }
}

}  // namespace sdfc::frontend
