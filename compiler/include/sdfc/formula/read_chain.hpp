#pragma once
// Reads a `formula:` node's body into a Chain; every mistake is reported to
// the reader's sink at its file:line:column. Empty after an error.
#include <optional>

#include "sdfc/formula/chain.hpp"
#include "sdfc/frontend/value_reader.hpp"

namespace sdfc::formula {

std::optional<Chain> read_chain(frontend::ValueReader& r, const SourceValue& body);

struct Preset;  // sdfc/formula/preset.hpp
// A preset's own node (`pseudo_kleinian: {...}`, at `key`) or a formula that
// names one (`formula: {preset: pseudo_kleinian, ...}`).
std::optional<Chain> read_preset(frontend::ValueReader& r, const Preset& p, const SourceValue& body, const SourceValue& key);
std::optional<Chain> read_named_preset(frontend::ValueReader& r, const SourceValue& body);

// The settings every chain has: iterations, bailout, julia, de, kleinian_size
// (the fallbacks: the given counts and c's own de and kleinian_size).
// In a 4-D chain julia may give w too (read after the steps).
void read_settings(frontend::ValueReader& r, frontend::MapReader& m, Chain& c, int iterations, double bailout);

}  // namespace sdfc::formula
