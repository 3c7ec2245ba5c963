#include "combinator.hpp"

#include <fmt/format.h>

#include <vector>

#include "../reference/materials.hpp"

namespace sdfc::kinds::combinator {

using domain::worse;
using ir::DistanceClass;

ir::Props fold_props(const ir::Node& n, const Kid& kid, Select s, double each) {
  // min/max of distances is a bound (exact outside for a union, not inside).
  ir::Props p;
  p.cls = DistanceClass::Bound;
  p.lipschitz = 0;
  p.bounds = kid(0).bounds;
  for (size_t i = 0; i < n.children.size(); ++i) {
    const ir::Props c = kid(i);
    p.cls = worse(p.cls, c.cls);
    p.lipschitz = std::max(p.lipschitz, c.lipschitz);
    p.cost += c.cost + each;
    if (i == 0) continue;
    if (s == Select::Nearer) p.bounds = p.bounds.united(c.bounds);
    if (s == Select::Farther) p.bounds = p.bounds.intersected(c.bounds);
  }
  return p;
}

Sample fold_samples(const ir::Graph& g, const ir::Node& n, const V3& p,
                    const std::function<void(Sample& acc, const Sample& b)>& step) {
  Sample acc = reference::evaluate(g, n.children[0], p);
  for (size_t i = 1; i < n.children.size(); ++i) step(acc, reference::evaluate(g, n.children[i], p));
  return acc;
}

void select_sample(Sample& acc, const Sample& b, Select s, double d) {
  bool take_b = (s == Select::Nearer && b.distance < acc.distance) || (s == Select::Farther && b.distance > acc.distance);
  if (take_b) acc = b;
  acc.distance = d;
}

void mix_sample(Sample& acc, const Sample& b, Select s, double nb, const std::function<double(double, double)>& blend) {
  bool take_b = (s == Select::Nearer && b.distance < acc.distance) || (s == Select::Farther && b.distance > acc.distance);
  acc = reference::detail::mix_samples(acc, b, reference::detail::share_of_b(blend, acc.distance, nb),
                                       blend(acc.distance, nb), take_b ? b.material : acc.material);
}

namespace {

// scene_material: folds child k's record into rec (the children before it,
// whose combined distance is d), before d takes k in. Smooth blends mix by
// the share of k in the blended distance (its derivative in k's distance);
// the intersection is -U(-a, -b) and the difference -U(-a, b), so their
// weights are the union's at the negated distances. Hard operations and
// the stylised blends take the nearer child; a difference keeps the first.
void fold_record(Walker& w, const ir::Node& n, const Fold& f, const std::string& rec, const std::string& d,
                 const Carried& k) {
  if (f.weight.empty()) {
    if (f.select != Select::First)
      w.line(fmt::format("{} = mat_select({}, {}, {} {} {});", rec, rec, k.rec, k.d,
                         f.select == Select::Nearer ? "<" : ">", d));
    return;
  }
  const auto& names = ir::info(n.kind).params;
  size_t radius_at = size_t(std::find(names.begin(), names.end(), "radius") - names.begin());
  std::string radius = "(real)(" + w.param(n, radius_at) + ")";  // may be animated
  std::string a = f.select == Select::Nearer ? d : "-" + d, b = f.select == Select::Farther ? "-" + k.d : k.d;
  w.line(fmt::format("{} = mat_mix({}, {}, {}({}, {}, {}));  // blend weight", rec, rec, k.rec, w.call(std::string(f.weight)),
                     a, b, radius));
}

}  // namespace

// A hard union whose last child is an object set (the gather_object_sets
// pass puts it there) folds the other children first and walks the set
// with their distance as its cull bound: the same minimum, fewer boxes.
bool culls_last_child(const Walker& w, const ir::Node& n, const Fold& f) {
  if (n.kind != ir::Kind::Union || f.select != Select::Nearer || !f.weight.empty() || n.children.size() < 2) return false;
  const ir::Node& last = w.graph().node(n.children.back());
  return last.kind == ir::Kind::ObjectSet && !last.props.corrected;
}

std::string dual_fold(Select s, const std::string& d, const std::string& b,
                      const std::function<std::string(const std::string&, const std::string&)>& blend) {
  auto neg = [](const std::string& x) { return x[0] == '-' ? "-(" + x + ")" : "-" + x; };
  return s == Select::Nearer    ? blend(d, b)
         : s == Select::Farther ? "-" + blend(neg(d), neg(b))
                                : "-" + blend(neg(d), b);
}

Carried combine(Walker& w, const ir::Node& n, const std::string& p, const Fold& f) {
  const codegen::detail::Literals& lit = w.lit();
  const bool cull = culls_last_child(w, n, f);
  std::vector<Carried> kids;
  for (size_t i = 0; i + (cull ? 1 : 0) < n.children.size(); ++i) kids.push_back(w.child(n.children[i], p));
  const bool with_mat = w.tracks_material();
  std::string d = w.var("d"), m = with_mat ? w.var("m") : "";
  w.line(fmt::format("real {} = {};  // {}", d, kids[0].d, w.describe(n)));
  bool track = with_mat;
  bool any_mat = cull && !w.tracks_trap();  // the set carries its items' materials (no trap)
  for (const auto& k : kids) any_mat = any_mat || k.mat != lit.typed(0);
  if (track && !any_mat) track = false, m = lit.typed(0);
  if (track) w.line(fmt::format("real {} = {};", m, kids[0].mat));
  const bool records = w.carries_records();
  std::string rec = records ? w.var("r") : "";
  if (records) w.line(fmt::format("mat_record {} = {};", rec, kids[0].rec));
  auto fold_in = [&](const Carried& k) {
    if (records) fold_record(w, n, f, rec, d, k);
    if (track && f.select != Select::First)
      w.line(fmt::format("{} = SEL({}, {}, {} {} {});", m, m, k.mat, k.d, f.select == Select::Nearer ? "<" : ">", d));
    w.line(fmt::format("{} = {};", d, f.fold(d, k.d)));
  };
  for (size_t i = 1; i < kids.size(); ++i) fold_in(kids[i]);
  if (cull) {
    w.cull_bound = w.above.empty() ? d : fmt::format("fmin({}, {})", d, w.above);
    Carried set = w.child(n.children.back(), p);
    w.cull_bound.clear();
    fold_in(set);
  }
  return {d, with_mat ? m : "", rec};
}

Dual fold_dual(DualWalker& w, const ir::Node& n, const std::string& p,
               const std::function<void(const Dual& v, const Dual& k)>& step) {
  std::vector<Dual> kids;
  for (ir::NodeId c : n.children) kids.push_back(w.child(c, p));
  Dual v{w.var("d"), w.var("g")};
  w.line(fmt::format("real {} = {};  // {}", v.d, kids[0].d, ir::info(n.kind).name));
  w.line(fmt::format("vec3 {} = {};", v.g, kids[0].g));
  for (size_t i = 1; i < kids.size(); ++i) step(v, kids[i]);
  return v;
}

}  // namespace sdfc::kinds::combinator
