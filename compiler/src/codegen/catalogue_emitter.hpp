#pragma once
// The call expression of a catalogue primitive (cone ... box_frame).
#include <optional>
#include <set>
#include <string>

#include "code_writer.hpp"
#include "sdfc/ir/graph.hpp"

namespace sdfc::codegen::detail {
// nullopt when n is not a catalogue primitive; adds the function to `used`.
std::optional<std::string> catalogue_call(const ir::Node& n, const std::string& p, const Literals& lit,
                                          std::set<std::string>& used);
}  // namespace sdfc::codegen::detail
