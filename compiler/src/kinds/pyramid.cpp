// pyramid: a square base of side `base` centred at z = -height/2, apex above.
#include "shape_math.hpp"

SDFC_KIND(Pyramid, 34, "pyramid", Primitive, 0, "base,height", "sd_pyramid")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct PyramidP {
  double base, height;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"base", "height"});
  frontend::Param base = m.param("base", 1, Range::positive()), height = m.param("height", 1, Range::positive());
  return l.make_animated({base, height});
}

ir::Props props(const ir::Node& n) {
  auto y = view<PyramidP>(n);
  return leaf(box(-y.base / 2, -y.base / 2, -y.height / 2, y.base / 2, y.base / 2, y.height / 2), 40);
}

// Squared distance in the base plane from (x, y)/base to the unit square.
double base_gap2(V p, double base) {
  double gx = std::max(std::fabs(p.x) / base - 0.5, 0.0), gy = std::max(std::fabs(p.y) / base - 0.5, 0.0);
  return gx * gx + gy * gy;
}

double distance(const ir::Node& n, const V3& pa) {
  auto py = view<PyramidP>(n);
  double base = py.base, height = py.height;
  V p = at(pa);
  // Unit base pyramid (Quilez), scaled by the base.
  double h = height / base;
  double x = std::fabs(p.x) / base, z = std::fabs(p.y) / base, y = (p.z + height / 2) / base;
  if (z > x) std::swap(x, z);
  x -= 0.5, z -= 0.5;
  double m2 = h * h + 0.25;
  double qx = z, qy = h * y - 0.5 * x, qz = h * x + 0.5 * y;
  double s = std::max(-qx, 0.0);
  double t = std::clamp((qy - 0.5 * z) / (m2 + 0.25), 0.0, 1.0);
  double a = m2 * (qx + s) * (qx + s) + qy * qy;
  double b = m2 * (qx + 0.5 * t) * (qx + 0.5 * t) + (qy - m2 * t) * (qy - m2 * t);
  double d2 = std::min(qy, -qx * m2 - qy * 0.5) > 0 ? 0 : std::min(a, b);
  double side = std::sqrt((d2 + qz * qz) / m2) * sgn(std::max(qz, -y));
  // Quilez's formula measures to the sloping faces; the base face is ours.
  if (y <= 0) return std::sqrt(base_gap2(p, base) + y * y) * base;
  return std::max(side, -y) * base;
}

constexpr ParamDoc k_docs[] = {
    {"base", "number", "1", "> 0", "the side of the square base at z = -height/2"},
    {"height", "number", "1", "> 0", "the apex is at z = +height/2"},
};

}  // namespace

namespace described {
extern const Description Pyramid{.kind = ir::Kind::Pyramid,
                                 .yaml = "pyramid",
                                 .example = "{pyramid: {base: 1.0, height: 0.8}}",
                                 .param_count = count_of<PyramidP>(),
                                 .lower = lower,
                                 .props = props,
                                 .call_args = "base, height",
                                 .distance = distance,
                                 .summary = "A square pyramid along z, its base down.",
                                 .docs = k_docs};
}

}  // namespace sdfc::kinds
