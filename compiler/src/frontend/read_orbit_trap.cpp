// orbit_trap: {palette: [[r, g, b], ...] | gradient: [{at: 0, color: [r, g, b]}, ...],
//              mix: 0.7, source: trap | iteration, range: auto | [lo, hi],
//              offset: 0, cycles: 1, repeat: clamp | repeat | mirror,
//              shape: cross | point | plane | line | sphere, point, normal, direction, radius}
#include "read_orbit_trap.hpp"

#include <fmt/format.h>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::frontend {

namespace {

constexpr size_t kMaxColours = 16;

void read_palette(ValueReader& r, const SourceValue& p, const std::string& what, ir::ColourSource& s) {
  if (!p.is_seq() || p.items.size() < 2 || p.items.size() > kMaxColours) {
    r.sink().error(p.loc, what + ".palette: expected a list of 2 to 16 colours [r, g, b]", "");
    return;
  }
  for (size_t i = 0; i < p.items.size(); ++i) {
    s.palette.push_back(r.vec3(p.items[i], what + ".palette", Range::closed(0, 1)));
    s.positions.push_back(double(i) / double(p.items.size() - 1));
  }
}

// gradient: stops with a position `at` in [0, 1], ascending.
void read_gradient(ValueReader& r, const SourceValue& g, const std::string& what, ir::ColourSource& s) {
  if (!g.is_seq() || g.items.size() < 2 || g.items.size() > kMaxColours) {
    r.sink().error(g.loc, what + ".gradient: expected a list of 2 to 16 stops, e.g. [{at: 0, color: [0, 0, 0]}, {at: 1, color: [1, 1, 1]}]", "");
    return;
  }
  for (const SourceValue& stop : g.items) {
    MapReader m(r, stop, what + ".gradient stop", {"at", "color"});
    if (!m.ok()) continue;
    double at = m.number("at", 0, Range::closed(0, 1));
    if (!m.require("at") || !m.require("color")) continue;
    if (!s.positions.empty() && at < s.positions.back())
      r.sink().error(m.get("at")->loc,
                     fmt::format("{}.gradient: stops must be in ascending order of 'at' ({} comes after {})", what, at,
                                 s.positions.back()),
                     "");
    s.positions.push_back(at);
    s.palette.push_back(m.vec3("color", {0, 0, 0}, Range::closed(0, 1)));
  }
}

}  // namespace

using Shape = ir::TrapShape::Kind;

// shape and the keys that place it; a key of another shape is refused.
void read_trap_shape(ValueReader& r, MapReader& m, const std::string& what, ir::TrapShape& t) {
  if (const SourceValue* v = m.get("shape"); v && v->is_scalar() && v->scalar == "axis") {
    r.sink().error(v->loc, what + ".shape: expected one of cross, point, plane, line, sphere, got 'axis'",
                   "an axis is 'shape: line', with 'point' and 'direction'");
    return;
  }
  const std::string shape = m.word("shape", "cross", {"cross", "point", "plane", "line", "sphere"});
  t.kind = shape == "point"    ? Shape::Point
           : shape == "plane"  ? Shape::Plane
           : shape == "line"   ? Shape::Line
           : shape == "sphere" ? Shape::Sphere
                               : Shape::Cross;
  struct Key {
    const char* name;
    bool wanted;
    const char* owner;
  };
  const Key keys[] = {{"point", t.kind != Shape::Cross, "point, plane, line and sphere"},
                      {"normal", t.kind == Shape::Plane, "plane"},
                      {"direction", t.kind == Shape::Line, "line"},
                      {"radius", t.kind == Shape::Sphere, "sphere"}};
  for (const Key& k : keys)
    if (const SourceValue* v = m.get(k.name); v && !k.wanted)
      r.sink().error(v->loc, fmt::format("{}.{}: belongs to shape {} (this trap's shape is {})", what, k.name, k.owner, shape),
                     "");
  t.point = m.vec3("point", {0, 0, 0});
  if (t.kind == Shape::Plane) t.direction = m.direction("normal", {0, 0, 1});
  if (t.kind == Shape::Line) t.direction = m.direction("direction", {0, 0, 1});
  t.radius = m.number("radius", 1, Range::positive());
}

void read_palette_walk(ValueReader& r, MapReader& m, const std::string& what, ir::ColourSource& s) {
  if (const SourceValue* range = m.get("range")) {
    if (range->is_scalar() && range->scalar == "auto") {
      s.range_auto = true;
    } else if (range->is_seq() && range->items.size() == 2) {
      s.range_auto = false;
      s.lo = r.number(range->items[0], what + ".range");
      s.hi = r.number(range->items[1], what + ".range");
      if (!(s.hi > s.lo))
        r.sink().error(range->loc, fmt::format("{}.range: expected [lo, hi] with lo < hi, got [{}, {}]", what, s.lo, s.hi), "");
    } else {
      r.sink().error(range->loc, what + ".range: expected 'auto' or [lo, hi]",
                     range->is_scalar() ? did_you_mean(range->scalar, {"auto"}) : "");
    }
  }
  s.offset = m.number("offset", 0, Range::closed(-100, 100));
  s.cycles = m.number("cycles", 1, Range::positive(1000));
  std::string rep = m.word("repeat", "clamp", {"clamp", "repeat", "mirror"});
  s.repeat = rep == "repeat"   ? ir::PaletteRepeat::Repeat
             : rep == "mirror" ? ir::PaletteRepeat::Mirror
                               : ir::PaletteRepeat::Clamp;
  const SourceValue* p = m.get("palette");
  const SourceValue* g = m.get("gradient");
  if (p && g) {
    r.sink().error(g->loc, what + ": give either 'palette' (evenly spaced colours) or 'gradient' (stops with positions), not both", "");
    return;
  }
  if (g) return read_gradient(r, *g, what, s);
  p = m.require("palette");
  if (p) read_palette(r, *p, what, s);
}

void read_orbit_trap(ValueReader& r, const SourceValue& v, ir::MaterialDef& md) {
  std::string what = "material '" + md.name + "'.orbit_trap";
  MapReader m(r, v, what,
              {"palette", "gradient", "mix", "source", "range", "offset", "cycles", "repeat", "shape", "point", "normal",
               "direction", "radius"});
  if (!m.ok()) return;
  md.trap_mix = m.number("mix", 0.7, Range::closed(0, 1));
  if (const SourceValue* s = m.get("source")) {
    if (s->is_scalar() && s->scalar == "iteration") md.trap_source = ir::MaterialDef::TrapSource::Iteration;
    else if (!s->is_scalar() || s->scalar != "trap")
      r.sink().error(s->loc, what + ".source: expected 'trap' or 'iteration' (normal and position colour: see 'coloring')",
                     s->is_scalar() ? did_you_mean(s->scalar, {"trap", "iteration"}) : "");
  }
  read_trap_shape(r, m, what, md.trap_shape);
  if (md.trap_source == ir::MaterialDef::TrapSource::Iteration && md.trap_shape.kind != Shape::Cross)
    r.sink().error(m.get("shape")->loc, what + ".shape: a shape is for source: trap (the iteration count has none)", "");
  ir::ColourSource s;
  read_palette_walk(r, m, what, s);
  md.trap_palette = std::move(s.palette);
  md.trap_positions = std::move(s.positions);
  md.trap_range_auto = s.range_auto;
  md.trap_lo = s.lo, md.trap_hi = s.hi, md.trap_offset = s.offset, md.trap_cycles = s.cycles;
  md.trap_repeat = s.repeat;
}

}  // namespace sdfc::frontend
