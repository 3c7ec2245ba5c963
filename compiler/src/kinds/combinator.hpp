#pragma once
// What the combinators share (csg.cpp, smooth_csg.cpp, blends.cpp): a fold
// over the children, left to right, in the properties pass, the reference
// and the scene walker. Which child's material a hard fold keeps is its
// `select`: the nearer (union), the farther (intersection) or the first
// (difference, whose cut face keeps the first child's material).
#include <functional>
#include <string>

#include "domain_op.hpp"

namespace sdfc::kinds::combinator {

using domain::Kid;
using reference::Sample;

enum class Select { Nearer, Farther, First };

// Bounds (united, intersected or the first child's), the worst class, the
// largest L and the children's costs plus `each` per child.
ir::Props fold_props(const ir::Node& n, const Kid& kid, Select s, double each);

// acc = step(acc, child i) over the children after the first.
Sample fold_samples(const ir::Graph& g, const ir::Node& n, const V3& p,
                    const std::function<void(Sample& acc, const Sample& b)>& step);
// A hard fold: the selected child's sample, distance `d`.
void select_sample(Sample& acc, const Sample& b, Select s, double d);
// A smooth fold blend(a, nb) (nb: b's distance as it enters, negated for a
// difference): the materials mix by b's share of the blended distance.
void mix_sample(Sample& acc, const Sample& b, Select s, double nb, const std::function<double(double, double)>& blend);

// The fold in the walker: `fold(d, b)` is the expression of the combined
// distance of d (the children so far) and b (the next child). With
// material records, `weight` (an op_weight_* function taking a, b and the
// node's `radius`) mixes them; without one they are selected.
struct Fold {
  Select select;
  std::function<std::string(const std::string& d, const std::string& b)> fold;
  std::string_view weight = {};
};
Carried combine(Walker& w, const ir::Node& n, const std::string& p, const Fold& f);

// A smooth family's fold from its union-style blend U: the union is U(d, b),
// the intersection and the difference its duals -U(-d, -b) and -U(-d, b).
// Negation brackets an expression that already starts with '-', so the
// kernel never reads "--" as a decrement.
std::string dual_fold(Select s, const std::string& d, const std::string& b,
                      const std::function<std::string(const std::string&, const std::string&)>& blend);

// render.normals: dual: the children's distances and gradients, folded
// into v (the first child's to start with) by step(v, next child).
Dual fold_dual(DualWalker& w, const ir::Node& n, const std::string& p,
               const std::function<void(const Dual& v, const Dual& k)>& step);


}  // namespace sdfc::kinds::combinator
