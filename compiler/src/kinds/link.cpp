// link: a chain link, a torus stretched along y.
#include <fmt/format.h>

#include "shape_math.hpp"

SDFC_KIND(Link, 32, "link", Primitive, 0, "half_length,major,minor", "sd_link")

namespace sdfc::kinds {
namespace {
using namespace math;
using frontend::Range;

struct LinkP {
  double half_length, major, minor;
};

ir::NodeId lower(Lowering& l) {
  frontend::MapReader m = l.map({"length", "major_radius", "minor_radius"});
  frontend::Param length = m.param("length", 0.5, Range::non_negative());
  frontend::Param major = m.param("major_radius", 0.4, Range::positive());
  frontend::Param minor = m.param("minor_radius", 0.1, Range::positive());
  // At every time: the largest minor radius against the smallest major one.
  if (minor.hi >= major.lo)
    l.fail(m, "minor_radius",
           fmt::format("link.minor_radius: {} must be less than major_radius ({})", minor.hi, major.lo));
  return l.make_animated({length.scaled(0.5), major, minor});
}

ir::Props props(const ir::Node& n) {
  auto k = view<LinkP>(n);
  double r = k.major + k.minor;
  return leaf(box(-r, -k.half_length - r, -k.minor, r, k.half_length + r, k.minor), 14);
}

double distance(const ir::Node& n, const V3& p) {
  auto k = view<LinkP>(n);
  double y = std::max(std::fabs(p[1]) - k.half_length, 0.0);
  return len2(len2(p[0], y) - k.major, p[2]) - k.minor;
}

constexpr ParamDoc k_docs[] = {
    {"length", "number", "0.5", ">= 0", "the length of the straight parts"},
    {"major_radius", "number", "0.4", "> 0", "the radius of the bends, to the middle of the wire"},
    {"minor_radius", "number", "0.1", "> 0, less than major_radius", "the radius of the wire"},
};

}  // namespace

namespace described {
extern const Description Link{.kind = ir::Kind::Link,
                              .yaml = "link",
                              .example = "{link: {length: 0.6, major_radius: 0.35, minor_radius: 0.1}}",
                              .param_count = count_of<LinkP>(),
                              .lower = lower,
                              .props = props,
                              .call_args = "half_length, major, minor",
                              .distance = distance,
                              .summary = "A chain link in the xy-plane, its straight parts along y.",
                              .docs = k_docs};
}

}  // namespace sdfc::kinds
