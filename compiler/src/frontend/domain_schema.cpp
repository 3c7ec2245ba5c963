#include "domain_schema.hpp"

#include <fmt/format.h>

#include <cmath>

#include "sdfc/expr/expr.hpp"

namespace sdfc::frontend {

using ir::Kind;
using ir::NodeId;

const std::vector<std::string_view>& domain_modifiers() {
  static const std::vector<std::string_view> k = {"elongate", "round",    "onion",        "shell",  "displace",
                                                  "twist",    "bend",     "mirror",       "symmetry", "polar_repeat",
                                                  "repeat"};
  return k;
}

namespace {

int axis_index(ValueReader& r, const SourceValue& v, std::string_view what) {
  std::string w = r.word(v, what, {"x", "y", "z"});
  return w == "x" ? 0 : w == "y" ? 1 : 2;
}

// {axis, rate} for twist and bend.
std::vector<double> axis_rate(ValueReader& r, const SourceValue& v, std::string_view what) {
  MapReader m(r, v, what, {"axis", "rate"});
  int axis = m.get("axis") ? axis_index(r, *m.get("axis"), fmt::format("{}.axis", what)) : 2;
  double rate = m.require("rate") ? m.number("rate", 0, Range::closed(-1000, 1000)) : 0;
  return {double(axis), rate};
}

}  // namespace

NodeId apply_domain_modifiers(ValueReader& r, ir::Builder& b, const SourceValue& node, NodeId n) {
  auto wrap = [&](Kind k, std::vector<double> params, const SourceValue& at) {
    return b.make(k, std::move(params), {n}, at.loc);
  };
  if (const SourceValue* v = node.find("elongate")) {
    Vec3d h = r.vec3(*v, "elongate", Range::non_negative());
    n = wrap(Kind::Elongate, {h[0] / 2, h[1] / 2, h[2] / 2}, *v);
  }
  if (const SourceValue* v = node.find("round")) n = wrap(Kind::Round, {r.number(*v, "round", Range::positive())}, *v);
  if (const SourceValue* v = node.find("onion")) {
    // A list makes several layers: each halves the wall into two thinner ones.
    if (v->is_seq()) {
      if (v->items.empty()) r.sink().error(v->loc, "onion: the list of thicknesses is empty", "give one thickness per layer");
      for (size_t i = 0; i < v->items.size(); ++i)
        n = wrap(Kind::Onion, {r.number(v->items[i], fmt::format("onion[{}]", i), Range::positive())}, v->items[i]);
    } else {
      n = wrap(Kind::Onion, {r.number(*v, "onion", Range::positive())}, *v);
    }
  }
  if (const SourceValue* v = node.find("shell")) n = wrap(Kind::Shell, {r.number(*v, "shell", Range::positive())}, *v);
  if (const SourceValue* v = node.find("displace")) {
    MapReader m(r, *v, "displace", {"expr"});
    if (const SourceValue* e = m.require("expr")) {
      if (!e->is_scalar()) {
        r.sink().error(e->loc, "displace.expr: expected an expression of x, y, z such as \"0.05*sin(10*x)\", got " + e->kind_name(), "");
      } else {
        try {
          // A quoted string's location is its opening quote; columns count from the text.
          SourceLoc at = e->loc;
          if (e->quoted) at.column += 1;
          expr::ExprPtr ex = expr::fold(expr::parse(e->scalar, at, {"x", "y", "z", "time"}));
          b.graph().expressions.push_back(ex);
          n = wrap(Kind::Displace, {double(b.graph().expressions.size() - 1)}, *v);
        } catch (const SceneError& err) {
          for (const auto& d : err.diagnostics()) r.sink().error(d.loc, d.message, d.hint);
        }
      }
    }
  }
  if (const SourceValue* v = node.find("twist")) n = wrap(Kind::Twist, axis_rate(r, *v, "twist"), *v);
  if (const SourceValue* v = node.find("bend")) n = wrap(Kind::Bend, axis_rate(r, *v, "bend"), *v);
  if (const SourceValue* v = node.find("mirror")) {
    std::vector<double> axes{0, 0, 0};
    if (v->is_seq()) {
      for (size_t i = 0; i < v->items.size(); ++i) axes[axis_index(r, v->items[i], fmt::format("mirror[{}]", i))] = 1;
    } else {
      axes[axis_index(r, *v, "mirror")] = 1;
    }
    n = wrap(Kind::Mirror, axes, *v);
  }
  if (const SourceValue* v = node.find("symmetry"))
    n = wrap(Kind::Symmetry, {r.word(*v, "symmetry", {"tetrahedral", "octahedral"}) == "octahedral" ? 1.0 : 0.0}, *v);
  if (const SourceValue* v = node.find("polar_repeat")) {
    MapReader m(r, *v, "polar_repeat", {"axis", "count"});
    int axis = m.get("axis") ? axis_index(r, *m.get("axis"), "polar_repeat.axis") : 2;
    int count = m.require("count") ? m.integer("count", 2, 2, 10000) : 2;
    n = wrap(Kind::PolarRepeat, {double(axis), double(count)}, *v);
  }
  if (const SourceValue* v = node.find("repeat")) {
    MapReader m(r, *v, "repeat", {"period", "count"});
    Vec3d period = m.require("period") ? m.vec3("period", {1, 1, 1}, Range::non_negative()) : Vec3d{1, 1, 1};
    std::vector<double> count{0, 0, 0};
    if (const SourceValue* c = m.get("count")) {
      count = r.vecn(*c, "repeat.count", 3, Range::closed(1, 100000));
      for (size_t i = 0; i < count.size(); ++i)
        if (count[i] != std::floor(count[i]))
          r.sink().error(c->is_seq() && i < c->items.size() ? c->items[i].loc : c->loc,
                         fmt::format("repeat.count: {} is not a whole number of copies", count[i]), "");
    }
    if (period[0] == 0 && period[1] == 0 && period[2] == 0)
      r.sink().error(v->loc, "repeat.period: every period is 0, so nothing repeats", "give the spacing per axis, e.g. [2, 2, 0]");
    for (int i = 0; i < 3; ++i)
      if (period[i] == 0) count[i] = 1;  // not repeated along this axis
    n = wrap(Kind::Repeat, {period[0], period[1], period[2], count[0], count[1], count[2]}, *v);
  }
  return n;
}

const std::vector<std::string_view>& blend_kinds() {
  static const std::vector<std::string_view> k = {
      "chamfer_union", "chamfer_intersection", "chamfer_difference", "round_union",  "round_intersection",
      "round_difference", "columns_union",     "columns_intersection", "columns_difference", "stairs_union",
      "stairs_intersection", "stairs_difference"};
  return k;
}

std::optional<NodeId> lower_blend(ValueReader& r, const SourceValue& key, const SourceValue& body,
                                  const ChildLowering& children) {
  const std::string& k = key.scalar;
  auto op_of = [](std::string_view suffix) {
    return suffix == "union" ? Kind::BlendUnion : suffix == "intersection" ? Kind::BlendIntersection : Kind::BlendDifference;
  };
  if (k == "smooth_union" || k == "smooth_intersection" || k == "smooth_difference") {
    const SourceValue* kind = body.is_map() ? body.find("kind") : nullptr;
    if (!kind) return std::nullopt;
    std::string style = r.word(*kind, k + ".kind", {"polynomial", "cubic", "exponential"});
    if (style == "polynomial") return std::nullopt;
    MapReader m(r, body, k, {"radius", "kind", "children"});
    Param radius = m.require("radius") ? m.param("radius", 0.1, Range::positive()) : Param(0.1);  // may be animated
    const SourceValue* kids = m.require("children");
    if (!kids) return ir::kNoNode;
    return children(op_of(k.substr(7)), *kids, {Param(style == "cubic" ? 0.0 : 1.0), radius, Param(1)});
  }
  size_t cut = k.find('_');
  if (cut == std::string::npos) return std::nullopt;
  std::string style = k.substr(0, cut), op = k.substr(cut + 1);
  double index = style == "chamfer" ? 2 : style == "round" ? 3 : style == "columns" ? 4 : style == "stairs" ? 5 : -1;
  if (index < 0 || (op != "union" && op != "intersection" && op != "difference")) return std::nullopt;
  bool stepped = index >= 4;
  MapReader m(r, body, k, stepped ? std::initializer_list<std::string_view>{"radius", "steps", "children"}
                                  : std::initializer_list<std::string_view>{"radius", "children"});
  double radius = m.require("radius") ? m.number("radius", 0.1, Range::positive()) : 0.1;
  int steps = stepped ? m.integer("steps", 4, 1, 1000) : 1;
  const SourceValue* kids = m.require("children");
  if (!kids) return ir::kNoNode;
  return children(op_of(op), *kids, {Param(index), Param(radius), Param(double(steps))});
}

}  // namespace sdfc::frontend
