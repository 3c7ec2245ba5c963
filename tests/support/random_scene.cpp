#include "random_scene.hpp"

#include <fmt/format.h>

#include <vector>

namespace sdfc::test {
namespace {

class Gen {
 public:
  explicit Gen(std::uint64_t seed) : s_(seed * 0x9E3779B97F4A7C15ull + 1) {}
  std::uint64_t next() {  // splitmix64
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double real(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) / double(1ull << 53); }
  int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }
  bool chance(double p) { return real(0, 1) < p; }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[next() % v.size()]; }
  std::string num(double lo, double hi) { return fmt::format("{:.3f}", real(lo, hi)); }
  std::string vec(double lo, double hi) { return "[" + num(lo, hi) + ", " + num(lo, hi) + ", " + num(lo, hi) + "]"; }

 private:
  std::uint64_t s_;
};

std::string primitive(Gen& g) {
  switch (g.integer(0, 19)) {
    case 0: return "sphere: {radius: " + g.num(0.2, 1) + "}";
    case 1: return "box: {size: " + g.vec(0.4, 1.5) + ", radius: " + g.num(0, 0.15) + "}";
    case 2: return "torus: {major_radius: " + g.num(0.5, 1) + ", minor_radius: " + g.num(0.05, 0.3) + "}";
    case 3: return "plane: {normal: [0, 0, 1], offset: " + g.num(-1.5, -0.8) + "}";
    case 4: return "cylinder: {radius: " + g.num(0.2, 0.8) + ", height: " + g.num(0.3, 1.5) + "}";
    case 5: return "capsule: {a: [0, 0, -0.5], b: " + g.vec(-0.5, 0.5) + ", radius: " + g.num(0.1, 0.3) + "}";
    case 6: return "cone: {radius: " + g.num(0.2, 0.8) + ", height: " + g.num(0.4, 1.5) + "}";
    case 7: return "capped_cone: {height: " + g.num(0.5, 1.5) + ", bottom_radius: " + g.num(0.3, 0.6) + ", top_radius: " + g.num(0, 0.3) + "}";
    case 8: return "round_cone: {height: 1.2, bottom_radius: " + g.num(0.3, 0.5) + ", top_radius: " + g.num(0.05, 0.25) + "}";
    case 9: return "ellipsoid: {radii: " + g.vec(0.2, 1) + "}";
    case 10: return "octahedron: {size: " + g.num(0.3, 1) + "}";
    case 11: return "hex_prism: {apothem: " + g.num(0.2, 0.6) + ", height: " + g.num(0.3, 1.2) + "}";
    case 12: return "tri_prism: {side: " + g.num(0.4, 1.2) + ", height: " + g.num(0.3, 1.2) + "}";
    case 13: return "link: {length: " + g.num(0.2, 0.6) + ", major_radius: " + g.num(0.3, 0.5) + ", minor_radius: " + g.num(0.05, 0.15) + "}";
    case 14: return "rounded_cylinder: {radius: " + g.num(0.4, 0.7) + ", height: " + g.num(0.6, 1.2) + ", edge_radius: " + g.num(0.02, 0.15) + "}";
    case 15: return "pyramid: {base: " + g.num(0.5, 1.2) + ", height: " + g.num(0.5, 1.2) + "}";
    case 16: return "segment: {a: [0, 0, -0.5], b: [0.3, 0.2, 0.5], radius: " + g.num(0.05, 0.2) + "}";
    case 17: return "triangle: {a: [-0.5, -0.5, 0], b: [0.5, -0.5, 0], c: [0, 0.5, 0], thickness: " + g.num(0.02, 0.1) + "}";
    case 18: return "quad: {a: [-0.5, -0.5, 0], b: [0.5, -0.5, 0], c: [0.5, 0.5, 0], d: [-0.5, 0.5, 0], thickness: " + g.num(0.02, 0.1) + "}";
    default: return "box_frame: {size: " + g.vec(0.6, 1.2) + ", edge: " + g.num(0.02, 0.08) + "}";
  }
}

std::string fractal(Gen& g) {
  switch (g.integer(0, 7)) {
    case 0: return "mandelbulb: {power: " + g.num(2, 9) + ", iterations: " + std::to_string(g.integer(2, 8)) + "}";
    case 1: return "mandelbulb: {power: 8, iterations: 6, julia: " + g.vec(-0.4, 0.4) + "}";
    case 2: return "mandelbox: {scale: " + g.pick<std::string>({"-1.5", "2", "-2.2"}) + ", iterations: " + std::to_string(g.integer(2, 10)) + "}";
    case 3: return "julia: {c: [-0.2, 0.6, 0.2, 0.2], iterations: " + std::to_string(g.integer(4, 12)) + "}";
    case 4: return "menger: {iterations: " + std::to_string(g.integer(1, 4)) + "}";
    case 5: return "sierpinski: {iterations: " + std::to_string(g.integer(2, 8)) + "}";
    case 6: return "kifs: {symmetry: " + g.pick<std::string>({"tetrahedral", "octahedral", "icosahedral", "menger"}) +
                   ", iterations: " + std::to_string(g.integer(2, 10)) + "}";
    default: {
      std::string steps = "[{mandelbulb: {power: 8}}";
      int n = g.integer(1, 3);
      for (int i = 1; i < n; ++i) steps += ", {mandelbox: {scale: 2}}";
      return "hybrid: {steps: " + steps + "], iterations: " + std::to_string(g.integer(2, 10)) + "}";
    }
  }
}

std::string modifiers(Gen& g, bool allow_domain) {
  std::string m;
  if (g.chance(0.5)) m += ", translate: " + g.vec(-0.6, 0.6);
  if (g.chance(0.3)) m += ", rotate: {axis: " + g.vec(0.1, 1) + ", degrees: " + g.num(-90, 90) + "}";
  else if (g.chance(0.2)) m += ", rotate: [" + g.num(-45, 45) + ", 0, " + g.num(-45, 45) + "]";
  if (g.chance(0.2)) m += ", scale: " + (g.chance(0.5) ? g.num(0.5, 1.5) : g.vec(0.6, 1.4));
  if (g.chance(0.3)) m += ", material: " + g.pick<std::string>({"red", "blue", "shiny"});
  if (g.chance(0.1)) m += ", step_factor: " + g.num(0.5, 1);
  if (!allow_domain) return m;
  switch (g.integer(0, 14)) {
    case 0: m += ", repeat: {period: [5, 5, 0]}"; break;
    case 1: m += ", repeat: {period: [5, 5, 5], count: [2, 2, 1]}"; break;
    case 2: m += ", mirror: " + g.pick<std::string>({"x", "[x, z]", "y"}); break;
    case 3: m += ", polar_repeat: {count: " + std::to_string(g.integer(2, 8)) + "}"; break;
    case 4: m += ", symmetry: " + g.pick<std::string>({"tetrahedral", "octahedral"}); break;
    case 5: m += ", twist: {axis: z, rate: " + g.num(0.1, 1.5) + "}"; break;
    case 6: m += ", bend: {axis: x, rate: " + g.num(0.1, 0.6) + "}"; break;
    case 7: m += ", elongate: " + g.vec(0, 0.5); break;
    case 8: m += ", round: " + g.num(0.01, 0.1); break;
    case 9: m += ", onion: " + g.num(0.01, 0.05); break;
    case 10: m += ", shell: " + g.num(0.02, 0.08); break;
    case 11: m += ", displace: {expr: \"" + g.num(0.01, 0.05) + "*sin(" + g.num(2, 10) + "*x)*sin(" + g.num(2, 10) + "*y)\"}"; break;
    default: break;
  }
  return m;
}

std::string node(Gen& g, int depth) {
  int what = depth >= 3 ? g.integer(0, 6) : g.integer(0, 12);
  std::string body;
  if (what <= 4) body = primitive(g);
  else if (what <= 6) body = fractal(g);
  else {
    static const std::vector<std::string> hard = {"union", "intersection", "difference"};
    static const std::vector<std::string> blends = {"smooth_union", "smooth_intersection", "smooth_difference",
                                                    "chamfer_union", "round_union", "columns_union", "stairs_union",
                                                    "chamfer_intersection", "stairs_difference", "columns_intersection"};
    int n = g.integer(2, 3);
    std::string kids;
    for (int i = 0; i < n; ++i) kids += (i ? ", " : "") + std::string("{") + node(g, depth + 1) + "}";
    if (what <= 8) {
      body = g.pick(hard) + ": [" + kids + "]";
    } else {
      std::string op = g.pick(blends), extra;
      if (op.rfind("smooth_", 0) == 0 && g.chance(0.5)) extra = ", kind: " + g.pick<std::string>({"polynomial", "cubic", "exponential"});
      if (op.rfind("stairs_", 0) == 0 || op.rfind("columns_", 0) == 0) extra = ", steps: " + std::to_string(g.integer(1, 5));
      body = op + ": {radius: " + g.num(0.05, 0.4) + extra + ", children: [" + kids + "]}";
    }
  }
  return body + modifiers(g, g.chance(0.4));
}

}  // namespace

std::string random_scene(std::uint64_t seed, int width, int height) {
  Gen g(seed);
  std::string s = fmt::format("# random scene {}\n", seed);
  s += "camera: {position: " + fmt::format("[{}, {}, {}]", g.num(-1, 1), g.num(-5, -3.5), g.num(0.5, 2)) +
       ", target: [0, 0, 0], fov: " + g.num(30, 60) + "}\n";
  s += fmt::format("render: {{width: {}, height: {}, normals: {}, samples: {}, tone_mapping: {}}}\n", width, height,
                   g.pick<std::string>({"tetrahedral", "central"}), g.integer(1, 2),
                   g.pick<std::string>({"clamp", "reinhard", "aces"}));
  s += "materials:\n  red: {color: [0.8, 0.2, 0.1]}\n  blue: {color: [0.1, 0.3, 0.9], specular: 0.6, shininess: 50}\n"
       "  shiny: {color: [0.9, 0.9, 0.9], reflectivity: " + g.num(0, 0.8) + "}\n";
  s += "lights:\n";
  static const std::vector<std::string> shadows = {"none", "hard", "soft"};
  s += "  - directional: {direction: " + g.vec(-1, -0.1) + ", shadows: " + g.pick(shadows) + ", shadow_steps: 32}\n";
  if (g.chance(0.5))
    s += "  - point: {position: " + g.vec(1, 3) + ", intensity: " + g.num(1, 5) + ", shadows: " + g.pick(shadows) + ", shadow_steps: 24}\n";
  if (g.chance(0.7)) s += "  - ambient: {intensity: " + g.num(0.1, 0.4) + "}\n";
  std::string fx;
  if (g.chance(0.25)) fx += g.chance(0.5) ? "  ambient_occlusion: {samples: 4, distance: 0.3}\n" : "  ambient_occlusion: {method: step_count}\n";
  if (g.chance(0.2)) fx += "  glow: {strength: " + g.num(0.1, 1) + ", radius: 0.2}\n";
  if (g.chance(0.2)) fx += "  fog: {density: " + g.num(0.01, 0.2) + (g.chance(0.5) ? ", height_falloff: 0.5" : "") + "}\n";
  if (g.chance(0.2)) fx += "  reflections: {depth: " + std::to_string(g.integer(1, 3)) + "}\n";
  if (!fx.empty()) s += "effects:\n" + fx;
  s += "scene: {" + node(g, 0) + "}\n";
  return s;
}

}  // namespace sdfc::test
