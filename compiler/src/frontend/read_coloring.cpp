// coloring: {mix: 1, sources: [{trap: {...}, weight: 0.7}, {normal: {...}, weight: 0.3}, ...]}
// Each source is one of trap, iteration, normal, position, with the palette
// keys of orbit_trap (palette or gradient, range, offset, cycles, repeat);
// trap takes the shape keys, normal and position an axis.
#include <fmt/format.h>

#include "read_orbit_trap.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::frontend {

namespace {

using Kind = ir::ColourSource::Kind;

constexpr size_t kMaxSources = 8;

struct KindName {
  const char* name;
  Kind kind;
};
constexpr KindName kKinds[] = {
    {"trap", Kind::Trap}, {"iteration", Kind::Iteration}, {"normal", Kind::Normal}, {"position", Kind::Position}};

void read_source(ValueReader& r, const SourceValue& v, const std::string& what, ir::MaterialDef& md, bool& orbit) {
  MapReader m(r, v, what, {"trap", "iteration", "normal", "position", "weight"});
  if (!m.ok()) return;
  const SourceValue* body = nullptr;
  ir::ColourSource s;
  std::string name;
  for (const KindName& k : kKinds)
    if (const SourceValue* b = m.get(k.name)) {
      if (body) {
        r.sink().error(b->loc, fmt::format("{}: one source per entry, and this one is '{}' already", what, name),
                       "give each source its own list entry");
        return;
      }
      body = b, s.kind = k.kind, name = k.name;
    }
  if (!body) {
    if (v.entries.size() > (m.get("weight") ? 1u : 0u)) return;  // an unknown key, reported with a suggestion
    r.sink().error(v.loc, what + ": expected one of trap, iteration, normal, position, e.g. {normal: {palette: [...]}, weight: 0.5}", "");
    return;
  }
  s.weight = m.number("weight", 1, Range::positive(1000));
  const std::string inner = what + "." + name;
  const bool is_orbit = s.kind == Kind::Trap || s.kind == Kind::Iteration;
  if (is_orbit && orbit) {
    r.sink().error(body->loc, inner + ": a material mixes one orbit value (trap or iteration) at most",
                   "colour the other by a second material");
    return;
  }
  orbit = orbit || is_orbit;
  if (s.kind == Kind::Trap) {
    MapReader b(r, *body, inner,
                {"palette", "gradient", "range", "offset", "cycles", "repeat", "shape", "point", "normal", "direction", "radius"});
    if (!b.ok()) return;
    read_trap_shape(r, b, inner, s.shape);
    read_palette_walk(r, b, inner, s);
    md.trap_shape = s.shape;
  } else if (s.kind == Kind::Iteration) {
    MapReader b(r, *body, inner, {"palette", "gradient", "range", "offset", "cycles", "repeat"});
    if (!b.ok()) return;
    read_palette_walk(r, b, inner, s);
    md.trap_source = ir::MaterialDef::TrapSource::Iteration;
  } else {
    MapReader b(r, *body, inner, {"palette", "gradient", "range", "offset", "cycles", "repeat", "axis"});
    if (!b.ok()) return;
    s.axis = b.direction("axis", {0, 0, 1});
    read_palette_walk(r, b, inner, s);
  }
  md.coloring.push_back(std::move(s));
}

}  // namespace

void read_coloring(ValueReader& r, const SourceValue& v, ir::MaterialDef& md) {
  std::string what = "material '" + md.name + "'.coloring";
  MapReader m(r, v, what, {"mix", "sources"});
  if (!m.ok()) return;
  md.coloring_mix = m.number("mix", 1, Range::closed(0, 1));
  const SourceValue* list = m.require("sources");
  if (!list) return;
  if (!list->is_seq() || list->items.empty() || list->items.size() > kMaxSources) {
    r.sink().error(list->loc, fmt::format("{}.sources: expected a list of 1 to {} sources, e.g. [{{trap: {{palette: [...]}}}}, {{normal: {{palette: [...]}}, weight: 0.3}}]", what, kMaxSources), "");
    return;
  }
  bool orbit = false;
  for (size_t i = 0; i < list->items.size(); ++i)
    read_source(r, list->items[i], fmt::format("{}.sources[{}]", what, i), md, orbit);
}

}  // namespace sdfc::frontend
