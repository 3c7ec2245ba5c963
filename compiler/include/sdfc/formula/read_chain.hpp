#pragma once
// Reads a `formula:` node's body into a Chain; every mistake is reported to
// the reader's sink at its file:line:column. Empty after an error.
#include <optional>

#include "sdfc/formula/chain.hpp"
#include "sdfc/frontend/value_reader.hpp"

namespace sdfc::formula {

std::optional<Chain> read_chain(frontend::ValueReader& r, const SourceValue& body);

}  // namespace sdfc::formula
