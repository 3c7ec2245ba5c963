#pragma once
// The kinds with a description, from the one generated table. The first
// use checks every description (a missing part throws, naming the kind).
#include <string_view>
#include <vector>

#include "sdfc/kinds/description.hpp"

namespace sdfc::kinds {

// The kinds a scene writes as a node of its own (primitives and fractals).
const std::vector<const Description*>& all();           // in kind id order
const Description* find(ir::Kind k);                    // null: not one of all()
// The described kinds with children (domain operations, transforms,
// combinators: their child_props, evaluate and walk hooks).
const std::vector<const Description*>& operations();    // in kind id order
const Description* operation(ir::Kind k);               // null: not one of operations()
const Description* find(std::string_view yaml);         // by the key scenes write
// One argument of the stdlib call: parameter `index`, a real or (width 3) a vec3.
struct CallArg {
  size_t index;
  int width;
};
const std::vector<CallArg>& call_args(ir::Kind k);
// Throws std::logic_error naming the kind when d misses a part its kind
// needs (the registry runs it on every description at first use).
void check(const Description& d);

}  // namespace sdfc::kinds
