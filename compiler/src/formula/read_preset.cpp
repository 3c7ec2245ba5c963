// Reading a preset: its own parameters (by name, with Mandelbulber's
// defaults and ranges) and the settings every chain has, then its build
// writes the steps.
#include <fmt/format.h>

#include <stdexcept>

#include "sdfc/formula/preset.hpp"
#include "sdfc/formula/read_chain.hpp"
#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

size_t PresetArgs::at(std::string_view name) const {
  size_t i = 0;
  for (const PresetParam& q : params_) {
    if (q.name == name) return i;
    i += size_t(q.width);
  }
  throw std::logic_error("preset: no parameter " + std::string(name));
}

Step& ChainBuilder::add(std::string_view step, std::vector<double> a) {
  Step st;
  st.def = find_step(step);
  if (!st.def) throw std::logic_error("preset: no step " + std::string(step));
  // numbers not given take the step's defaults
  size_t at = 0;
  for (const StepParam& q : st.def->params) {
    if (a.size() <= at) a.insert(a.end(), q.fallback.begin(), q.fallback.begin() + q.width);
    at += size_t(q.width);
  }
  st.a = std::move(a);
  st.loc = at_;
  c_.steps.push_back(std::move(st));
  return c_.steps.back();
}

Step& ChainBuilder::expr(const char* x, const char* y, const char* z) {
  Step st;
  st.def = find_step("expr");
  st.loc = at_;
  const char* text[3] = {x, y, z};
  for (size_t i = 0; i < 3; ++i)
    if (text[i]) st.e[i] = expr::fold(expr::parse(text[i], at_, {"x", "y", "z", "cx", "cy", "cz"}));
  differentiate(st);
  c_.steps.push_back(std::move(st));
  return c_.steps.back();
}

std::optional<Chain> read_preset(frontend::ValueReader& r, const Preset& p, const SourceValue& body, const SourceValue& key) {
  const bool clean = r.sink().empty();
  const bool named = key.scalar == "preset";  // formula: {preset: NAME, ...}
  std::vector<std::string_view> keys;
  for (const PresetParam& q : p.params) keys.push_back(q.name);
  keys.insert(keys.end(), {"iterations", "bailout", "julia", "de", "kleinian_size"});
  if (named) keys.insert(keys.begin(), "preset");
  const SourceValue empty = [&] {
    SourceValue e;
    e.kind = SourceValue::Kind::Map;
    e.loc = key.loc;
    return e;
  }();
  const std::string what = named ? "formula" : std::string(p.name);
  frontend::MapReader m(r, body.is_null() ? empty : body, what, keys);
  if (!m.ok()) return std::nullopt;
  std::vector<double> values;
  for (const PresetParam& q : p.params) {
    const frontend::Range range = frontend::Range::closed(q.lo, q.hi);
    if (q.width == 1) {
      values.push_back(m.number(q.name, q.fallback[0], range));
    } else if (q.width == 4) {
      const SourceValue* v = m.get(q.name);
      std::vector<double> x = v ? r.vecn(*v, what + "." + std::string(q.name), 4, range)
                                : std::vector<double>(q.fallback.begin(), q.fallback.end());
      values.insert(values.end(), x.begin(), x.end());
    } else {
      auto v = m.vec3(q.name, {q.fallback[0], q.fallback[1], q.fallback[2]}, range);
      values.insert(values.end(), v.begin(), v.end());
    }
  }
  Chain c;
  c.preset = std::string(p.name);
  ChainBuilder b(c, key.loc);
  const PresetArgs args(p.params, std::move(values));
  p.build(args, b);  // may set de and kleinian_size
  for (const Step& st : c.steps)
    if (st.def->name == "quaternion" && st.a[0] != 2 && st.a[0] != 3) {  // the julia preset's degree
      const SourceValue* v = m.get("degree");
      r.sink().error(v ? v->loc : key.loc, fmt::format("{}.degree: must be 2 or 3, got {}", what, st.a[0]));
      break;
    }
  read_settings(r, m, c, p.iterations, p.bailout);
  if (p.as_builtin) c.builtin = p.as_builtin(args, c);
  if (!clean || !r.sink().empty()) return std::nullopt;
  return c;
}

std::optional<Chain> read_named_preset(frontend::ValueReader& r, const SourceValue& body) {
  const SourceValue* key = nullptr;
  for (const auto& [k, v] : body.entries)
    if (k.scalar == "preset") key = &k;
  const SourceValue& name = *body.find("preset");
  const Preset* p = name.is_scalar() ? find_preset(name.scalar) : nullptr;
  if (!p) {
    std::vector<std::string_view> names;
    std::string all;
    for (const Preset* q : presets()) {
      names.push_back(q->name);
      all += (all.empty() ? "" : ", ") + std::string(q->name);
    }
    std::string hint = name.is_scalar() ? did_you_mean(name.scalar, names) : "";
    r.sink().error(name.loc,
                   name.is_scalar() ? fmt::format("formula.preset: unknown preset '{}'", printable(name.scalar, 80))
                                    : "formula.preset: expected a preset's name, got " + name.kind_name(),
                   hint.empty() ? "presets: " + all : hint);
    return std::nullopt;
  }
  return read_preset(r, *p, body, *key);
}

}  // namespace sdfc::formula
