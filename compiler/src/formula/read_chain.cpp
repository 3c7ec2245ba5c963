#include "sdfc/formula/read_chain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

namespace {

using frontend::Range;

class ChainReader {
 public:
  explicit ChainReader(frontend::ValueReader& r) : r_(r) {}
  void error(const SourceLoc& at, std::string msg, std::string hint = {}) {
    r_.sink().error(at, std::move(msg), std::move(hint));
    bad_ = true;
  }
  bool bad() const { return bad_; }

  // One entry of `iterate:`: a name, or a one-key map name: value.
  void step(const SourceValue& item, size_t index, Chain& out) {
    const SourceValue* name = &item;
    const SourceValue* value = nullptr;
    if (item.is_map()) {
      if (item.entries.size() != 1) {
        error(item.loc, fmt::format("formula.iterate[{}]: expected one step such as 'box_fold: {{limit: 1}}', got a map of {} keys",
                                    index, item.entries.size()));
        return;
      }
      name = &item.entries[0].first;
      value = &item.entries[0].second;
    } else if (!item.is_scalar()) {
      error(item.loc, fmt::format("formula.iterate[{}]: expected a step such as 'add_c' or 'scale: 2', got {}", index,
                                  item.kind_name()));
      return;
    }
    const StepDef* def = find_step(name->scalar);
    if (!def) {
      std::vector<std::string_view> names;
      for (const StepDef* d : steps()) names.push_back(d->name);
      std::string all;
      for (auto n : names) all += (all.empty() ? "" : ", ") + std::string(n);
      std::string hint = did_you_mean(name->scalar, names);
      error(name->loc, fmt::format("formula.iterate[{}]: unknown step '{}'", index, printable(name->scalar, 80)),
            hint.empty() ? "steps: " + all : hint);
      return;
    }
    Step st;
    st.def = def;
    st.loc = name->loc;
    int repeat = 1;
    const std::string what = fmt::format("formula.iterate[{}].{}", index, def->name);
    if (value && !value->is_null() && !value->is_map()) {
      // the shorthand `scale: 2` sets the step's first number
      const StepParam* first = def->params.empty() ? nullptr : &def->params.front();
      if (first && first->width == 3 && value->is_seq()) {
        // `scale_xyz: [1, 2, 1]` sets its first vec3
        const StepParam& q = *first;
        auto x = r_.vec3(*value, what, Range::closed(q.lo, q.hi));
        st.a.insert(st.a.end(), x.begin(), x.end());
        for (size_t i = 1; i < def->params.size(); ++i) fallback(def->params[i], st, value->loc, what);
      } else if (!first || first->width != 1) {
        error(value->loc, fmt::format("{}: expected a map of the step's settings, got {}", what, value->kind_name()),
              def->params.empty() ? "this step takes no settings: write '- " + std::string(def->name) + "'" : "");
        return;
      } else {
        const StepParam& q = *first;
        st.a.push_back(q.words.empty() ? r_.number(*value, what, Range::closed(q.lo, q.hi)) : word(*value, q, what));
        for (size_t i = 1; i < def->params.size(); ++i) fallback(def->params[i], st, value->loc, what);
      }
    } else {
      const SourceValue empty;
      const SourceValue& m = value && value->is_map() ? *value : empty;
      known_keys(m, *def, what);
      for (const StepParam& q : def->params) {
        const SourceValue* v = m.find(q.name);
        std::string key = what + "." + std::string(q.name);
        if (!v) {
          fallback(q, st, value ? value->loc : name->loc, what);
        } else if (!q.words.empty()) {
          st.a.push_back(word(*v, q, key));
        } else if (q.width == 1) {
          st.a.push_back(r_.number(*v, key, Range::closed(q.lo, q.hi)));
        } else {
          auto x = r_.vec3(*v, key, Range::closed(q.lo, q.hi));
          if ((q.name == "axis" || q.name == "normal") && std::hypot(x[0], x[1], x[2]) < 1e-9)
            error(v->loc, key + ": must not be the zero vector", "give a direction such as [0, 0, 1]");
          st.a.insert(st.a.end(), x.begin(), x.end());
        }
      }
      if (def->name == "scale" && std::fabs(st.a[0]) < 1e-6) error(m.find("scale") ? m.find("scale")->loc : st.loc, what + ": scale must not be 0");
      if (def->name == "expr") expressions(m, st, what, value ? value->loc : name->loc);
      if (const SourceValue* v = m.find("repeat")) repeat = r_.integer(*v, what + ".repeat", 1, kMaxRepeat);
      if (const SourceValue* v = m.find("from")) st.from = r_.integer(*v, what + ".from", 0, kMaxIterations);
      if (const SourceValue* v = m.find("until")) st.until = r_.integer(*v, what + ".until", 0, kMaxIterations);
      windows_.push_back({out.steps.size(), m.find("from") ? m.find("from")->loc : st.loc,
                          m.find("until") ? m.find("until")->loc : st.loc});
    }
    entry_start_.push_back(out.steps.size());
    if (def->name == "scale_xyz" && std::min({std::fabs(st.a[0]), std::fabs(st.a[1]), std::fabs(st.a[2])}) < 1e-6)
      error(value ? value->loc : st.loc, what + ": no factor may be 0", "a zero factor flattens space and the estimate breaks");
    if (def->name == "quaternion" && st.a[0] != 2 && st.a[0] != 3)
      error(value ? value->loc : st.loc, fmt::format("{}: power must be 2 or 3, got {}", what, st.a[0]));
    for (int k = 0; k < repeat; ++k) out.steps.push_back(st);
  }

  // from/until inside the iterations, until after from.
  void check_windows(const Chain& c) {
    for (const Window& w : windows_) {
      const Step& st = c.steps.at(w.first);
      if (st.from >= c.iterations)
        error(w.from, fmt::format("{}: from: {} is past the last iteration ({} iterations run 0 to {})", st.def->name, st.from,
                                c.iterations, c.iterations - 1));
      else if (st.until != kMaxIterations && st.until > c.iterations)
        error(w.until, fmt::format("{}: until: {} is past the iterations ({})", st.def->name, st.until, c.iterations),
              "until is the first iteration the step no longer runs on; at most the iteration count");
      else if (st.until <= st.from)
        error(w.until, fmt::format("{}: until: {} must come after from: {}", st.def->name, st.until, st.from));
    }
  }

 private:
  struct Window {
    size_t first;  // the step's first copy
    SourceLoc from, until;
  };

  void fallback(const StepParam& q, Step& st, const SourceLoc& at, const std::string& what) {
    if (q.required) error(at, fmt::format("{}: missing '{}'", what, q.name), "");
    st.a.insert(st.a.end(), q.fallback.begin(), q.fallback.begin() + q.width);
  }

  // A word-valued setting: the index of the word, or an error with the nearest.
  double word(const SourceValue& v, const StepParam& q, const std::string& key) {
    for (size_t i = 0; i < q.words.size(); ++i)
      if (v.is_scalar() && v.scalar == q.words[i]) return double(i);
    std::string all;
    for (auto w : q.words) all += (all.empty() ? "" : ", ") + std::string(w);
    std::string hint = v.is_scalar() ? did_you_mean(v.scalar, q.words) : "";
    error(v.loc,
          v.is_scalar() ? fmt::format("{}: unknown {} '{}'", key, q.name, printable(v.scalar, 80))
                        : fmt::format("{}: expected one of {}, got {}", key, all, v.kind_name()),
          hint.empty() ? std::string(q.name) + "s: " + all : hint);
    return q.fallback[0];
  }

  void known_keys(const SourceValue& m, const StepDef& def, const std::string& what) {
    std::vector<std::string_view> keys;
    for (const StepParam& q : def.params) keys.push_back(q.name);
    if (def.name == "expr") keys.insert(keys.end(), {"x", "y", "z"});
    keys.insert(keys.end(), {"repeat", "from", "until"});
    for (const auto& [k, v] : m.entries) {
      bool ok = false;
      for (auto a : keys) ok = ok || k.scalar == a;
      if (ok) continue;
      std::string all;
      for (auto a : keys) all += (all.empty() ? "" : ", ") + std::string(a);
      std::string hint = did_you_mean(k.scalar, keys);
      error(k.loc, fmt::format("unknown key '{}' in {}", printable(k.scalar, 80), what), hint.empty() ? "allowed: " + all : hint);
    }
  }

  void expressions(const SourceValue& m, Step& st, const std::string& what, const SourceLoc& at) {
    const char* names[3] = {"x", "y", "z"};
    bool any = false;
    for (int i = 0; i < 3; ++i) {
      const SourceValue* v = m.find(names[i]);
      if (!v) continue;
      any = true;
      std::string key = what + "." + names[i];
      if (!v->is_scalar()) {
        error(v->loc, key + ": expected an expression of x, y, z, cx, cy, cz such as \"x*x - y*y\", got " + v->kind_name());
        continue;
      }
      SourceLoc start = v->loc;
      if (v->quoted) start.column += 1;  // a quoted string's location is its opening quote
      try {
        expr::ExprPtr e = expr::fold(expr::parse(v->scalar, start, {"x", "y", "z", "cx", "cy", "cz", "time"}));
        if (expr::uses(e, "time"))
          error(v->loc, key + ": a formula's expr cannot use time", "animate the scene's other values instead");
        st.e[size_t(i)] = e;
      } catch (const SceneError& err) {
        for (const auto& d : err.diagnostics()) error(d.loc, d.message, d.hint);
      }
    }
    if (!any) error(at, what + ": give at least one of x, y, z (the new components of z)");
    differentiate(st);
  }

  frontend::ValueReader& r_;
  bool bad_ = false;
  std::vector<Window> windows_;

 public:
  std::vector<size_t> entry_start_;  // per entry of iterate: its first step after repeats
};

}  // namespace

void read_settings(frontend::ValueReader& r, frontend::MapReader& m, Chain& c, int iterations, double bailout) {
  c.iterations = m.integer("iterations", iterations, 1, kMaxIterations);
  c.bailout = m.number("bailout", bailout, Range::closed(1, 1e6));
  if (const SourceValue* v = m.get("julia")) {
    c.julia = true;
    const bool four = v->is_seq() && v->items.size() == 4;
    if (four && four_d(c)) {
      // a 4-D chain's constant: x, y, z and w
      std::vector<double> x = r.vecn(*v, "formula.julia", 4);
      c.c = {x[0], x[1], x[2]};
      c.cw = x[3];
    } else if (four) {
      r.sink().error(v->loc, "formula.julia: 4 numbers need a 4-D chain, this chain's z has 3 components",
                     "give [x, y, z], or add a step that uses w (quaternion, hypercomplex, aexion)");
    } else if (four_d(c) && v->is_seq() && v->items.size() != 3) {
      r.sink().error(v->loc, fmt::format("formula.julia: expected 3 or 4 numbers (x, y, z and w), got {}", v->items.size()));
    } else {
      c.c = m.vec3("julia", {0, 0, 0});  // in a 4-D chain c's w keeps its value
    }
  }
  // A preset's own choice is the default (the words in DeChoice's order).
  static const char* const kWords[] = {"auto", "linear", "log", "jacobian", "kleinian", "jos_kleinian"};
  std::string de = m.word("de", kWords[int(c.de)], {"auto", "linear", "log", "jacobian", "kleinian", "jos_kleinian"});
  c.de = de == "linear"     ? DeChoice::Linear
         : de == "log"      ? DeChoice::Log
         : de == "jacobian" ? DeChoice::Jacobian
         : de == "kleinian" ? DeChoice::Kleinian
         : de == "jos_kleinian" ? DeChoice::JosKleinian
                            : DeChoice::Auto;
  c.kleinian_size = m.number("kleinian_size", c.kleinian_size, Range::closed(1e-6, 1e6));
}

std::optional<Chain> read_chain(frontend::ValueReader& r, const SourceValue& body) {
  if (body.is_map() && body.find("preset")) return read_named_preset(r, body);
  const bool clean = r.sink().empty();  // the reader's own errors do not tell us
  ChainReader cr(r);
  frontend::MapReader m(r, body, "formula", {"iterations", "bailout", "iterate", "julia", "de", "kleinian_size", "repeat_from"});
  if (!m.ok()) return std::nullopt;
  Chain c;
  const SourceValue* list = m.require("iterate");
  if (!list) return std::nullopt;
  if (!list->is_seq() || list->items.empty()) {
    cr.error(list->loc, "formula.iterate: expected a list of steps such as [box_fold, sphere_fold, {scale: 2}, add_c], got " +
                            list->kind_name());
    return std::nullopt;
  }
  for (size_t i = 0; i < list->items.size(); ++i) {
    cr.step(list->items[i], i, c);
    if (c.steps.size() > size_t(kMaxSteps)) {
      cr.error(list->items[i].loc, fmt::format("formula.iterate: more than {} steps (repeats count)", kMaxSteps),
               "a longer chain makes a kernel too slow to compile; use fewer steps or more iterations");
      return std::nullopt;
    }
  }
  read_settings(r, m, c, 12, 100);  // after the steps: julia's count depends on them
  if (const SourceValue* v = m.get("repeat_from")) {
    int entry = r.integer(*v, "formula.repeat_from", 0, kMaxSteps);
    if (entry >= int(list->items.size()))
      cr.error(v->loc, fmt::format("formula.repeat_from: {} is past the last step (iterate lists {} steps, 0 to {})", entry,
                                   list->items.size(), list->items.size() - 1));
    else if (entry < int(cr.entry_start_.size()))
      c.repeat_from = int(cr.entry_start_[size_t(entry)]);
  }
  if (!cr.bad()) cr.check_windows(c);
  if (cr.bad() || (clean && !r.sink().empty())) return std::nullopt;
  return c;
}

}  // namespace sdfc::formula
