// round, onion and shell: the child's distance offset, its surface grown
// outwards (round), turned into a hollow skin (onion) or hollowed inside
// (shell).
#include "domain_op.hpp"

SDFC_KIND(Round,              45, "round",               Transform,  1, "radius",                        "")
SDFC_KIND(Onion,              46, "onion",               Transform,  1, "thickness",                     "")
SDFC_KIND(Shell,              47, "shell",               Transform,  1, "thickness",                     "")

namespace sdfc::kinds {
namespace {
using namespace domain;

// round's radius, onion's and shell's thickness.
struct OffsetP {
  double by;
};

// round and onion move the surface out by their parameter.
ir::Props grown_props(const ir::Graph&, const ir::Node& n, const Kid& kid) {
  ir::Props p = bound_of(kid, 2);
  if (p.bounds.finite()) p.bounds = p.bounds.padded(view<OffsetP>(n).by);
  return p;
}
ir::Props shell_props(const ir::Graph&, const ir::Node&, const Kid& kid) { return bound_of(kid, 3); }

template <double (*F)(double d, double by)>
Sample offset_evaluate(const ir::Graph& g, const ir::Node& n, const V3& p) {
  Sample s = child_at(g, n, p);
  s.distance = F(s.distance, view<OffsetP>(n).by);
  return s;
}
double round_of(double d, double r) { return d - r; }
double onion_of(double d, double t) { return std::fabs(d) - t; }
double shell_of(double d, double t) { return std::max(d, -d - t); }

// The child's value with its distance d rewritten as `form` of d and the parameter.
Carried offset_walk(Walker& w, const ir::Node& n, const std::string& p, const char* form) {
  Carried c = w.child(n.children[0], p);
  std::string d = w.var("d");
  std::string e = fmt::format(fmt::runtime(form), c.d, w.param(n, SDFC_AT(OffsetP, by)));
  w.line(fmt::format("real {} = {};  // {}", d, e, w.describe(n)));
  return with_d(c, d);
}
Carried round_walk(Walker& w, const ir::Node& n, const std::string& p) { return offset_walk(w, n, p, "{} - {}"); }
Carried onion_walk(Walker& w, const ir::Node& n, const std::string& p) { return offset_walk(w, n, p, "fabs({}) - {}"); }
Carried shell_walk(Walker& w, const ir::Node& n, const std::string& p) {
  return offset_walk(w, n, p, "fmax({0}, -{0} - {1})");
}

}  // namespace

namespace described {
extern const Description Round{.kind = ir::Kind::Round,
                               .yaml = "round",
                               .param_count = count_of<OffsetP>(),
                               .child_props = grown_props,
                               .evaluate = offset_evaluate<round_of>,
                               .walk = round_walk};
extern const Description Onion{.kind = ir::Kind::Onion,
                               .yaml = "onion",
                               .param_count = count_of<OffsetP>(),
                               .child_props = grown_props,
                               .evaluate = offset_evaluate<onion_of>,
                               .walk = onion_walk};
extern const Description Shell{.kind = ir::Kind::Shell,
                               .yaml = "shell",
                               .param_count = count_of<OffsetP>(),
                               .child_props = shell_props,
                               .evaluate = offset_evaluate<shell_of>,
                               .walk = shell_walk};
}

}  // namespace sdfc::kinds
