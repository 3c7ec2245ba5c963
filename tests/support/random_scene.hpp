#pragma once
// A seeded generator of valid scenes: every node kind (primitives, fractals,
// combinators and blends), modifier, domain operation, effect and light,
// with random parameters inside their documented ranges. The same seed
// gives the same YAML text on every machine (its own integer generator, not
// the standard distributions, whose results vary between libraries).
#include <cstdint>
#include <string>

namespace sdfc::test {

// A small scene (`width` x `height` pixels) in YAML.
std::string random_scene(std::uint64_t seed, int width = 8, int height = 8);

}  // namespace sdfc::test
