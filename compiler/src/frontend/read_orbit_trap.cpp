// orbit_trap: {palette: [[r, g, b], ...] | gradient: [{at: 0, color: [r, g, b]}, ...],
//              mix: 0.7, source: trap | iteration, range: auto | [lo, hi],
//              offset: 0, cycles: 1, repeat: clamp | repeat | mirror}
#include "read_orbit_trap.hpp"

#include <fmt/format.h>

#include "sdfc/support/diagnostics.hpp"

namespace sdfc::frontend {

namespace {

constexpr size_t kMaxColours = 16;

void read_palette(ValueReader& r, const SourceValue& p, const std::string& what, ir::MaterialDef& md) {
  if (!p.is_seq() || p.items.size() < 2 || p.items.size() > kMaxColours) {
    r.sink().error(p.loc, what + ".palette: expected a list of 2 to 16 colours [r, g, b]", "");
    return;
  }
  for (size_t i = 0; i < p.items.size(); ++i) {
    md.trap_palette.push_back(r.vec3(p.items[i], what + ".palette", Range::closed(0, 1)));
    md.trap_positions.push_back(double(i) / double(p.items.size() - 1));
  }
}

// gradient: stops with a position `at` in [0, 1], ascending.
void read_gradient(ValueReader& r, const SourceValue& g, const std::string& what, ir::MaterialDef& md) {
  if (!g.is_seq() || g.items.size() < 2 || g.items.size() > kMaxColours) {
    r.sink().error(g.loc, what + ".gradient: expected a list of 2 to 16 stops, e.g. [{at: 0, color: [0, 0, 0]}, {at: 1, color: [1, 1, 1]}]", "");
    return;
  }
  for (const SourceValue& stop : g.items) {
    MapReader s(r, stop, what + ".gradient stop", {"at", "color"});
    if (!s.ok()) continue;
    double at = s.number("at", 0, Range::closed(0, 1));
    if (!s.require("at") || !s.require("color")) continue;
    if (!md.trap_positions.empty() && at < md.trap_positions.back())
      r.sink().error(s.get("at")->loc,
                     fmt::format("{}.gradient: stops must be in ascending order of 'at' ({} comes after {})", what, at,
                                 md.trap_positions.back()),
                     "");
    md.trap_positions.push_back(at);
    md.trap_palette.push_back(s.vec3("color", {0, 0, 0}, Range::closed(0, 1)));
  }
}

}  // namespace

void read_orbit_trap(ValueReader& r, const SourceValue& v, ir::MaterialDef& md) {
  std::string what = "material '" + md.name + "'.orbit_trap";
  MapReader m(r, v, what, {"palette", "gradient", "mix", "source", "range", "offset", "cycles", "repeat"});
  if (!m.ok()) return;
  md.trap_mix = m.number("mix", 0.7, Range::closed(0, 1));
  if (const SourceValue* s = m.get("source")) {
    if (s->is_scalar() && s->scalar == "iteration") md.trap_source = ir::MaterialDef::TrapSource::Iteration;
    else if (!s->is_scalar() || s->scalar != "trap")
      r.sink().error(s->loc, what + ".source: expected 'trap' or 'iteration'",
                     s->is_scalar() ? did_you_mean(s->scalar, {"trap", "iteration"}) : "");
  }
  if (const SourceValue* range = m.get("range")) {
    if (range->is_scalar() && range->scalar == "auto") {
      md.trap_range_auto = true;
    } else if (range->is_seq() && range->items.size() == 2) {
      md.trap_range_auto = false;
      md.trap_lo = r.number(range->items[0], what + ".range");
      md.trap_hi = r.number(range->items[1], what + ".range");
      if (!(md.trap_hi > md.trap_lo))
        r.sink().error(range->loc, fmt::format("{}.range: expected [lo, hi] with lo < hi, got [{}, {}]", what, md.trap_lo, md.trap_hi),
                       "");
    } else {
      r.sink().error(range->loc, what + ".range: expected 'auto' or [lo, hi]",
                     range->is_scalar() ? did_you_mean(range->scalar, {"auto"}) : "");
    }
  }
  md.trap_offset = m.number("offset", 0, Range::closed(-100, 100));
  md.trap_cycles = m.number("cycles", 1, Range::positive(1000));
  std::string rep = m.word("repeat", "clamp", {"clamp", "repeat", "mirror"});
  md.trap_repeat = rep == "repeat"   ? ir::MaterialDef::TrapRepeat::Repeat
                   : rep == "mirror" ? ir::MaterialDef::TrapRepeat::Mirror
                                     : ir::MaterialDef::TrapRepeat::Clamp;
  const SourceValue* p = m.get("palette");
  const SourceValue* g = m.get("gradient");
  if (p && g) {
    r.sink().error(g->loc, what + ": give either 'palette' (evenly spaced colours) or 'gradient' (stops with positions), not both", "");
    return;
  }
  if (g) return read_gradient(r, *g, what, md);
  p = m.require("palette");
  if (p) read_palette(r, *p, what, md);
}

}  // namespace sdfc::frontend
