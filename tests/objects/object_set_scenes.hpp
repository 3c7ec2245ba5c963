#pragma once
// The object-set tests' scenes: scattered spheres and boxes in three
// materials, as single shapes or smooth groups, beside other children.
#include <fmt/format.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sdfc/frontend/lower_scene.hpp"
#include "sdfc/passes/passes.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::test {

inline const char* kHead =
    "camera: {position: [0, -9, 5], target: [0, 0, 1], up: [0, 0, 1], fov: 50}\n"
    "render: {width: 96, height: 64}\n"
    "lights:\n  - directional: {direction: [-0.4, 0.6, -0.7]}\n  - ambient: {intensity: 0.3}\n"
    "materials:\n  a: {color: [0.9, 0.2, 0.1]}\n  b: {color: [0.1, 0.3, 0.9], reflectivity: 0.3}\n"
    "  c: {color: [0.2, 0.8, 0.2]}\n"
    "scene:\n  union:\n";

// n scattered spheres and boxes (materials a, b, c in turn), optionally
// smooth unions of `group` of them, and `extra` lines of other children.
inline std::string scene(size_t n, size_t group = 1, const std::string& extra = "", double spread = 4, unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-spread, spread), r(0.15, 0.4);
  std::string s = kHead + extra;
  const char* mats[] = {"a", "b", "c"};
  auto shape = [&](const std::string& indent, V3 c) {
    std::string out = (rng() % 2) ? fmt::format("{}- sphere: {{radius: {:.3f}}}\n", indent, r(rng))
                                  : fmt::format("{}- box: {{size: [{:.3f}, {:.3f}, {:.3f}]}}\n", indent, 2 * r(rng),
                                                2 * r(rng), 2 * r(rng));
    return out + fmt::format("{}  translate: [{:.3f}, {:.3f}, {:.3f}]\n", indent, c[0], c[1], c[2]);
  };
  for (size_t i = 0; i < n / group; ++i) {
    V3 c{u(rng), u(rng), 1 + 0.5 * u(rng)};
    if (group == 1) {
      s += shape("    ", c) + fmt::format("      material: {}\n", mats[i % 3]);
      continue;
    }
    s += "    - smooth_union:\n        radius: 0.3\n        children:\n";
    for (size_t k = 0; k < group; ++k) s += shape("          ", {c[0] + 0.3 * k, c[1], c[2] + 0.2 * k});
    s += fmt::format("      material: {}\n", mats[i % 3]);
  }
  return s;
}

// The scene as code: every pass but gather_object_sets.
inline ir::Module unrolled(const std::string& yaml) {
  ir::Module m = lower_scene(load_yaml_text(yaml, "test.yaml"), "test.yaml");
  for (const auto& p : passes::pipeline())
    if (p.name != "gather_object_sets") m = p.run(std::move(m));
  return m;
}


struct Case {
  std::string name;
  std::string yaml;
  double spread;
  bool seen_whole = true;  // the set sees the world's points: the camera's cone, bounded normals
};

// The set turned and moved as one: it sees other points than the camera's
// rays, so it is walked whole (a cone in the rays' frame would cull the
// items it must measure, and the rays would pass through them).
inline std::string turned(const std::string& yaml) {
  const std::string head = "scene:\n  union:\n";
  const size_t at = yaml.find(head) + head.size();
  std::string out = yaml.substr(0, at) + "    - union:\n";
  std::istringstream body(yaml.substr(at));
  for (std::string line; std::getline(body, line);) out += "    " + line + "\n";
  return out + "      rotate: [0, 0, 30]\n      translate: [0.5, 0, 0]\n";
}

inline std::vector<Case> cases() {
  return {{"flat", scene(300), 5},
          {"groups", scene(400, 4), 5},
          {"with_floor", scene(200, 1, "    - plane: {normal: [0, 0, 1], offset: -0.5}\n      material: c\n"), 5},
          {"coincident", scene(100, 1, "", 0.0), 1},
          {"far_apart", scene(100, 1, "", 2000), 2000},
          {"turned", turned(scene(200)), 6, false}};
}

}  // namespace sdfc::test
