#include "catalogue_emitter.hpp"

#include <fmt/format.h>

namespace sdfc::codegen::detail {

std::optional<std::string> catalogue_call(const ir::Node& n, const std::string& p, const Literals& lit,
                                          std::set<std::string>& used) {
  using ir::Kind;
  const auto& q = n.params;
  auto r = [&](size_t i) { return lit.real(q[i]); };
  auto v = [&](size_t i) { return lit.vec3({q[i], q[i + 1], q[i + 2]}); };
  std::string args;
  switch (n.kind) {
    case Kind::Cone: args = fmt::format("{}, {}", r(0), r(1)); break;
    case Kind::CappedCone:
    case Kind::RoundCone: args = fmt::format("{}, {}, {}", r(0), r(1), r(2)); break;
    case Kind::Ellipsoid: args = v(0); break;
    case Kind::Octahedron: args = r(0); break;
    case Kind::HexPrism:
    case Kind::TriPrism:
    case Kind::Pyramid: args = fmt::format("{}, {}", r(0), r(1)); break;
    case Kind::Link:
    case Kind::RoundedCylinder: args = fmt::format("{}, {}, {}", r(0), r(1), r(2)); break;
    case Kind::Triangle: args = fmt::format("{}, {}, {}, {}", v(0), v(3), v(6), r(9)); break;
    case Kind::Quad: args = fmt::format("{}, {}, {}, {}, {}", v(0), v(3), v(6), v(9), r(12)); break;
    case Kind::BoxFrame: args = fmt::format("{}, {}", v(0), r(3)); break;
    default: return std::nullopt;
  }
  std::string fn(ir::info(n.kind).stdlib_function);
  used.insert(fn);
  return fmt::format("{}({}, {})", fn, p, args);
}

}  // namespace sdfc::codegen::detail
