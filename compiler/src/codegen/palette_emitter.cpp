#include "palette_emitter.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sdfc::codegen::detail {

// x = (value - lo) / (hi - lo) * cycles + offset is the position along the
// palette (0 = its first colour, 1 = its last); clamp holds the ends, repeat
// starts again at the first colour, mirror walks back. Between two stops the
// colour is linear; before the first and after the last stop it is flat.
void emit_trap_palette(CodeWriter& w, const Literals& lit, const ir::MaterialDef& md, size_t i) {
  const auto& pal = md.trap_palette;
  const auto& at = md.trap_positions;
  w.open("{");
  const double span = md.trap_hi - md.trap_lo;
  w.line(fmt::format("real x = (trap - {}) * {} + {};  // value -> palette position (range [{:.4g}, {:.4g}]{})",
                     lit.real(md.trap_lo), lit.real(md.trap_cycles / span), lit.real(md.trap_offset), md.trap_lo,
                     md.trap_hi, md.trap_range_auto ? ", measured on the surface" : ""));
  switch (md.trap_repeat) {
    case ir::MaterialDef::TrapRepeat::Clamp: w.line("x = clamp(x, K(0.0f), K(1.0f));"); break;
    case ir::MaterialDef::TrapRepeat::Repeat: w.line("x = x - floor(x);  // repeat"); break;
    case ir::MaterialDef::TrapRepeat::Mirror:
      w.line("x = 1.0f - fabs(x - 2.0f * floor(0.5f * x) - 1.0f);  // mirror: 0 -> 1 -> 0");
      break;
  }
  w.line(fmt::format("vec3 pal = {};", lit.vec3(pal[0])));
  for (size_t k = 0; k + 1 < pal.size(); ++k) {
    double width = std::max(at[k + 1] - at[k], 1e-9);
    w.line(fmt::format("pal = v3_select(pal, v3_mix({}, {}, fmin((x - {}) * {}, K(1.0f))), x >= {});", lit.vec3(pal[k]),
                       lit.vec3(pal[k + 1]), lit.real(at[k]), lit.real(1.0 / width), lit.real(at[k])));
  }
  w.line(fmt::format("*albedo = v3_select(*albedo, v3_mix(*albedo, pal, {}), is{});", lit.typed(md.trap_mix), i));
  w.close("}");
}

}  // namespace sdfc::codegen::detail
