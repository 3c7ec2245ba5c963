// The estimator a chain gets, and the table of chains by index.
#include <fmt/format.h>

#include <deque>
#include <map>
#include <mutex>
#include <tuple>

#include "sdfc/formula/step.hpp"

namespace sdfc::formula {

bool four_d(const Chain& c) {
  for (const Step& s : c.steps)
    if (s.def->four_d) return true;
  return false;
}

Plan plan(const Chain& c) {
  Plan p;
  const Step* non_conformal = nullptr;
  const Step* power = nullptr;
  for (const Step& s : c.steps) {
    if (!non_conformal && !s.def->conformal(s)) non_conformal = &s;
    if (!power && s.def->power && !(s.def->name == "expr" && s.linear)) power = &s;
  }
  std::string derivative;
  if (c.de == DeChoice::Jacobian) {
    p.jacobian = true;
    derivative = "running Jacobian (de: jacobian)";
  } else if (non_conformal) {
    p.jacobian = true;
    derivative = fmt::format("running Jacobian: {} (line {}) is not conformal, a scalar derivative could overshoot",
                             non_conformal->def->name, non_conformal->loc.line);
  } else {
    derivative = "scalar derivative: every step is conformal with a known factor";
  }
  std::string form;
  if (c.de == DeChoice::Kleinian) {
    p.kleinian = true;
    form = fmt::format("max(rxy - {}, |rxy z.z| / r) / |dr| (de: kleinian)", c.kleinian_size);
  } else if (c.de == DeChoice::JosKleinian) {
    p.jos_kleinian = true;
    form = fmt::format("min({}, {}) / max(|dr|, {}) (de: jos_kleinian), cut to the bailout ball",
                       c.jos_height > 0 ? fmt::format("min(z.y, {} - z.y)", c.jos_height) : "z.y", c.jos_cap, c.jos_min_dr);
  } else if (c.de == DeChoice::Linear || c.de == DeChoice::Log) {
    p.log = c.de == DeChoice::Log;
    form = p.log ? "0.5 log(r) r / |dr| (de: log)" : "r / |dr| (de: linear)";
  } else if (power) {
    p.log = true;
    form = fmt::format("0.5 log(r) r / |dr|: {} (line {}) grows like a power of |z|", power->def->name, power->loc.line);
  } else {
    form = "r / |dr|: folds and scales grow |z| linearly";
  }
  p.why = form + "; " + derivative;
  if (const Step* s = power ? power : non_conformal) p.leans_on = fmt::format("{} (line {})", s->def->name, s->loc.line);
  return p;
}

namespace {
std::string show_step(const Step& s) {
  std::string out(s.def->name);
  size_t at = 0;
  for (const StepParam& q : s.def->params) {
    if (!q.words.empty())
      out += fmt::format(" {} {}", q.name, q.words.at(size_t(s.a[at])));
    else if (q.width == 1)
      out += fmt::format(" {} {}", q.name, s.a[at]);
    else
      out += fmt::format(" {} [{}, {}, {}]", q.name, s.a[at], s.a[at + 1], s.a[at + 2]);
    at += size_t(q.width);
  }
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    if (s.e[size_t(i)]) out += fmt::format(" {} = {}", names[i], expr::to_string(s.e[size_t(i)]));
  if (s.period > 0)
    out += fmt::format(" (iterations {}..{} of every {})", s.from, s.until - 1, s.period);
  else if (s.from != 0 || s.until != kMaxIterations)
    out += s.until == kMaxIterations ? fmt::format(" (iterations {}..)", s.from)
                                     : fmt::format(" (iterations {}..{})", s.from, s.until - 1);
  return out;
}
}  // namespace

std::string describe(const Chain& c) {
  std::string out = c.preset.empty() ? "" : fmt::format("preset {} expands to:\n", c.preset);
  if (four_d(c))
    out += fmt::format("formula (4-D: z has a fourth component w, starting at {}): {} iterations, bailout {}, {}\n", c.w_start,
                       c.iterations, c.bailout,
                       c.julia ? fmt::format("julia c = [{}, {}, {}, {}]", c.c[0], c.c[1], c.c[2], c.cw) : "c = the point (w 0)");
  else
    out += fmt::format("formula: {} iterations, bailout {}, {}\n", c.iterations, c.bailout,
                       c.julia ? fmt::format("julia c = [{}, {}, {}]", c.c[0], c.c[1], c.c[2]) : "c = the point");
  if (c.set_radius > 0) out += fmt::format("  the set lies within radius {} (the far field and bounds use it)\n", c.set_radius);
  for (size_t i = 0; i < c.steps.size(); ++i)
    out += fmt::format("  {}{}. {}\n", i, c.repeat_from == int(i) && i ? " (repeat from here)" : "", show_step(c.steps[i]));
  out += "  estimator: " + plan(c).why + "\n";
  return out;
}

namespace {
struct Table {
  std::mutex lock;
  std::deque<Chain> chains;
  std::map<std::string, size_t> by_text;
  std::map<std::tuple<std::string, int, int>, size_t> builtin_at;  // source location -> chain
};
Table& table() {
  static Table t;
  return t;
}
}  // namespace

size_t intern(Chain c) {
  // The description plus the exact numbers identify a chain.
  std::string key = describe(c);
  for (const Step& s : c.steps)
    for (double v : s.a) key += fmt::format(" {:a}", v);
  key += fmt::format(" {:a} {} {} {:a}", c.bailout, int(c.de), c.repeat_from, c.kleinian_size);
  if (c.de == DeChoice::JosKleinian) key += fmt::format(" {:a} {:a} {:a}", c.jos_cap, c.jos_min_dr, c.jos_height);
  if (c.set_radius > 0) key += fmt::format(" set {:a}", c.set_radius);
  if (c.bounds_trust > 0) key += fmt::format(" trust {:a}", c.bounds_trust);
  Table& t = table();
  std::lock_guard<std::mutex> g(t.lock);
  auto it = t.by_text.find(key);
  if (it != t.by_text.end()) return it->second;
  t.chains.push_back(std::move(c));
  return t.by_text[key] = t.chains.size() - 1;
}

const Chain& chain(size_t index) {
  Table& t = table();
  std::lock_guard<std::mutex> g(t.lock);
  return t.chains.at(index);
}

namespace {
std::tuple<std::string, int, int> place(const SourceLoc& at) { return {at.file ? *at.file : "", at.line, at.column}; }
}  // namespace

void note_builtin(const SourceLoc& at, size_t chain_index) {
  Table& t = table();
  std::lock_guard<std::mutex> g(t.lock);
  t.builtin_at[place(at)] = chain_index;
}

std::optional<size_t> builtin_chain_at(const SourceLoc& at) {
  Table& t = table();
  std::lock_guard<std::mutex> g(t.lock);
  auto it = t.builtin_at.find(place(at));
  if (it == t.builtin_at.end()) return std::nullopt;
  return it->second;
}

}  // namespace sdfc::formula
