#include "kind_call.hpp"

#include <fmt/format.h>

#include "sdfc/kinds/registry.hpp"

namespace sdfc::codegen::detail {

std::string kind_args(const ir::Node& n, const Literals& lit, bool animated) {
  std::string args;
  for (const kinds::CallArg& a : kinds::call_args(n.kind)) {
    if (!args.empty()) args += ", ";
    const size_t i = a.index;
    if (!animated)
      args += a.width == 3 ? lit.vec3({n.params[i], n.params[i + 1], n.params[i + 2]}) : lit.real(n.params[i]);
    else
      args += a.width == 3 ? param3(n, i, lit) : param(n, i, lit);
  }
  return args;
}

std::optional<std::string> kind_call(const ir::Node& n, const std::string& p, const Literals& lit,
                                     std::set<std::string>& used) {
  const kinds::Description* d = kinds::find(n.kind);
  if (!d || d->own_code) return std::nullopt;
  std::string args = kind_args(n, lit);
  std::string fn(ir::info(n.kind).stdlib_function);
  used.insert(fn);
  return fmt::format("{}({}, {})", fn, p, args);
}

}  // namespace sdfc::codegen::detail
