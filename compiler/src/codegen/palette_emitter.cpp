#include "palette_emitter.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sdfc::codegen::detail {

namespace {

// material i's orbit_trap as a coloring source: the palette walk is the same.
ir::ColourSource trap_source(const ir::MaterialDef& md) {
  ir::ColourSource s;
  s.palette = md.trap_palette;
  s.positions = md.trap_positions;
  s.range_auto = md.trap_range_auto;
  s.lo = md.trap_lo, s.hi = md.trap_hi, s.offset = md.trap_offset, s.cycles = md.trap_cycles;
  s.repeat = md.trap_repeat;
  return s;
}

const char* source_name(ir::ColourSource::Kind k) {
  switch (k) {
    case ir::ColourSource::Kind::Trap: return "trap";
    case ir::ColourSource::Kind::Iteration: return "smooth iteration count";
    case ir::ColourSource::Kind::Normal: return "normal";
    case ir::ColourSource::Kind::Position: return "position";
  }
  return "";
}

}  // namespace

// x = (value - lo) / (hi - lo) * cycles + offset is the position along the
// palette (0 = its first colour, 1 = its last); clamp holds the ends, repeat
// starts again at the first colour, mirror walks back. Between two stops the
// colour is linear; before the first and after the last stop it is flat.
void emit_palette_lookup(CodeWriter& w, const Literals& lit, const ir::ColourSource& s, const std::string& value) {
  const auto& pal = s.palette;
  const auto& at = s.positions;
  const double span = s.hi - s.lo;
  w.line(fmt::format("real x = ({} - {}) * {} + {};  // value -> palette position (range [{:.4g}, {:.4g}]{})", value,
                     lit.real(s.lo), lit.real(s.cycles / span), lit.real(s.offset), s.lo, s.hi,
                     !s.range_auto                                 ? ""
                     : s.kind == ir::ColourSource::Kind::Normal   ? ", auto: every way the surface can face"
                     : s.kind == ir::ColourSource::Kind::Position ? ", auto: the shapes' extent"
                                                                  : ", measured on the surface"));
  switch (s.repeat) {
    case ir::PaletteRepeat::Clamp: w.line("x = clamp(x, K(0.0f), K(1.0f));"); break;
    case ir::PaletteRepeat::Repeat: w.line("x = x - floor(x);  // repeat"); break;
    case ir::PaletteRepeat::Mirror: w.line("x = 1.0f - fabs(x - 2.0f * floor(0.5f * x) - 1.0f);  // mirror: 0 -> 1 -> 0"); break;
  }
  w.line(fmt::format("vec3 pal = {};", lit.vec3(pal[0])));
  for (size_t k = 0; k + 1 < pal.size(); ++k) {
    double width = std::max(at[k + 1] - at[k], 1e-9);
    w.line(fmt::format("pal = v3_select(pal, v3_mix({}, {}, fmin((x - {}) * {}, K(1.0f))), x >= {});", lit.vec3(pal[k]),
                       lit.vec3(pal[k + 1]), lit.real(at[k]), lit.real(1.0 / width), lit.real(at[k])));
  }
}

void emit_trap_palette(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i) {
  w.open("{");
  emit_palette_lookup(w, lit, trap_source(md), "trap");
  w.line(fmt::format("*albedo = v3_select(*albedo, v3_mix(*albedo, pal, {}), is{});", lit.typed(md.trap_mix), i));
  w.close("}");
}

// Each source's palette colour, weighted (the weights scaled to sum to 1),
// then mixed into the albedo by coloring.mix.
void emit_coloring(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i) {
  double total = 0;
  for (const auto& s : md.coloring) total += s.weight;
  w.open("{");
  w.line("vec3 mixed = v3_splat(0.0f);  // coloring: the sources' colours, weighted");
  for (const auto& s : md.coloring) {
    std::string value = "trap";  // the orbit's value: the trap, or the smooth iteration count for that source
    if (s.kind == ir::ColourSource::Kind::Normal) value = "v3_dot(n, " + lit.vec3(s.axis) + ")";
    if (s.kind == ir::ColourSource::Kind::Position) value = "v3_dot(p, " + lit.vec3(s.axis) + ")";
    w.open(fmt::format("{{  // source: {}, weight {:.4g}", source_name(s.kind), s.weight / total));
    emit_palette_lookup(w, lit, s, value);
    w.line(fmt::format("mixed = v3_mad(mixed, pal, {});", lit.typed(s.weight / total)));
    w.close("}");
  }
  w.line(fmt::format("*albedo = v3_select(*albedo, v3_mix(*albedo, mixed, {}), is{});", lit.typed(md.coloring_mix), i));
  w.close("}");
}

}  // namespace sdfc::codegen::detail
