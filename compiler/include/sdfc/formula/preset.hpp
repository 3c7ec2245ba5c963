#pragma once
// A preset: a named chain with its own parameters (Mandelbulber's names and
// defaults), written as a node of its own (`pseudo_kleinian: {...}`) or
// named in a formula (`formula: {preset: pseudo_kleinian, ...}`). Its
// `build` turns the parameters into the chain's steps; `sdfc check` prints
// the chain it expands to.
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "sdfc/formula/chain.hpp"

namespace sdfc::formula {

struct PresetParam {
  std::string_view name;
  int width;  // 1, 3 or 4 (a quaternion)
  std::array<double, 4> fallback;
  double lo, hi;
  std::string_view what;  // one line for the docs
};

// The values a scene gave (or the defaults), by name.
class PresetArgs {
 public:
  PresetArgs(const std::vector<PresetParam>& params, std::vector<double> values) : params_(params), v_(std::move(values)) {}
  double n(std::string_view name) const { return v_.at(at(name)); }
  std::array<double, 3> v(std::string_view name) const {
    size_t i = at(name);
    return {v_.at(i), v_.at(i + 1), v_.at(i + 2)};
  }
  std::array<double, 4> v4(std::string_view name) const {
    size_t i = at(name);
    return {v_.at(i), v_.at(i + 1), v_.at(i + 2), v_.at(i + 3)};
  }

 private:
  size_t at(std::string_view name) const;
  const std::vector<PresetParam>& params_;
  std::vector<double> v_;
};

// What a preset's build writes into: steps by name with their numbers in
// the step's own order (vec3s as three), at the preset's location.
class ChainBuilder {
 public:
  ChainBuilder(Chain& c, SourceLoc at) : c_(c), at_(at) {}
  Step& add(std::string_view step, std::vector<double> a = {});
  // An expr step: the new x, y, z as functions of x, y, z, cx, cy, cz.
  Step& expr(const char* x, const char* y, const char* z);
  Chain& chain() { return c_; }

 private:
  Chain& c_;
  SourceLoc at_;
};

struct Preset {
  std::string_view name;
  std::string_view what;  // one line for the docs and `sdfc check`
  std::vector<PresetParam> params;
  int iterations;
  double bailout;
  void (*build)(const PresetArgs&, ChainBuilder&);
  std::string_view builtin = {};  // the hand-wired kind it spells out, if any
  // The built-in kind's node when the kind draws exactly these values (its
  // ranges hold and no setting only a chain has is given); the preset then
  // renders with the kind's own code. Empty: the chain.
  std::optional<KindNode> (*as_builtin)(const PresetArgs&, const Chain&) = nullptr;
};

const std::vector<const Preset*>& presets();  // every preset, by name
const Preset* find_preset(std::string_view name);

// lo <= v <= hi: the as_builtin functions' test of a kind's range.
inline bool within(double v, double lo, double hi) { return v >= lo && v <= hi; }

}  // namespace sdfc::formula
