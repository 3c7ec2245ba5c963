#pragma once
// The stdlib call of a described kind (sdfc/kinds/): its function and its
// arguments, in the order its description names them.
#include <optional>
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::codegen::detail {
// The call's arguments after the point; `animated` false writes every
// parameter's value at time 0 (what the dual-normal gradient has always used).
std::string kind_args(const ir::Node& n, const Literals& lit, bool animated = true);
// nullopt when n's kind has no description; adds the function to `used`.
std::optional<std::string> kind_call(const ir::Node& n, const std::string& p, const Literals& lit,
                                     std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
