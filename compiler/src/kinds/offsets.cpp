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

namespace {
constexpr ParamDoc k_round_docs[] = {
    {"round", "number", "", "> 0", "how far the surface moves out"},
};
constexpr ParamDoc k_onion_docs[] = {
    {"onion", "number or list of numbers", "", "each > 0", "half the wall's thickness"},
};
constexpr ParamDoc k_shell_docs[] = {
    {"shell", "number", "", "> 0", "the wall's thickness"},
};
}  // namespace

namespace described {
extern const Description Round{.kind = ir::Kind::Round,
                               .yaml = "round",
                               .example = "{box: {size: [0.8, 0.8, 0.8]}, round: 0.1}",
                               .param_count = count_of<OffsetP>(),
                               .child_props = grown_props,
                               .evaluate = offset_evaluate<round_of>,
                               .walk = round_walk,
                               .summary = "Grows the shape by `r`, rounding its edges.",
                               .written_as = "`round: r` on any node",
                               .docs = k_round_docs};
extern const Description Onion{.kind = ir::Kind::Onion,
                               .yaml = "onion",
                               .example = "{difference: [{sphere: {radius: 0.7}, onion: 0.05}, {box: {size: [1, 1, 1]}, translate: [0.5, -0.5, 0.5]}]}",
                               .param_count = count_of<OffsetP>(),
                               .child_props = grown_props,
                               .evaluate = offset_evaluate<onion_of>,
                               .walk = onion_walk,
                               .summary = "A wall of 2 × `t` around the surface; a list nests one layer per entry.",
                               .written_as = "`onion: t` or `onion: [t1, t2, ...]` on any node",
                               .docs = k_onion_docs};
extern const Description Shell{.kind = ir::Kind::Shell,
                               .yaml = "shell",
                               .example = "{difference: [{box: {size: [1, 1, 1]}, shell: 0.06}, {box: {size: [1, 1, 1]}, translate: [0.5, -0.5, 0.5]}]}",
                               .param_count = count_of<OffsetP>(),
                               .child_props = shell_props,
                               .evaluate = offset_evaluate<shell_of>,
                               .walk = shell_walk,
                               .summary = "Hollows the solid: a wall of thickness `t` inside the surface.",
                               .written_as = "`shell: t` on any node",
                               .docs = k_shell_docs};
}

}  // namespace sdfc::kinds
