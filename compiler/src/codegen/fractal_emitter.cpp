// Fractal nodes to OpenCL C: each fractal's description (compiler/src/kinds/)
// writes its estimator and its orbit; this looks it up.
#include "fractal_emitter.hpp"

#include "../kinds/fractal.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc::codegen::detail {

bool is_fractal(const ir::Node& n) { return ir::info(n.kind).category == ir::Category::Fractal; }

std::string emit_fractal(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                         std::set<std::string>& used) {
  const kinds::Description* d = kinds::find(n.kind);
  if (!d || !d->emit) return "";
  kinds::Emitter e{n, p, lit, w, used};
  return d->emit(e);
}

std::string emit_fractal_trap(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used, OrbitValue value, std::optional<size_t> shape) {
  const kinds::Description* d = kinds::find(n.kind);
  if (!d || !d->emit_orbit) return "";
  kinds::Emitter e{n, p, lit, w, used, value, shape};
  return d->emit_orbit(e);
}

std::string emit_fractal_dual(const ir::Node& n, const std::string& p, const Literals& lit, CodeWriter& w,
                              std::set<std::string>& used) {
  const kinds::Description* d = kinds::find(n.kind);
  if (!d || !d->emit_dual) return "";
  kinds::Emitter e{n, p, lit, w, used};
  return d->emit_dual(e);
}

}  // namespace sdfc::codegen::detail
