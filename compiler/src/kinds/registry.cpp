#include "sdfc/kinds/registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "../frontend/animated_node.hpp"
#include "sdfc/kinds/lowering.hpp"

namespace sdfc::kinds {

namespace described {
#define DESCRIBED(e) extern const Description e;
#include "sdfc/kinds/described_kinds.def"  // generated: compiler/kinds.cmake
#undef DESCRIBED
}  // namespace described

namespace {

// "a, radius" against the row's "ax,ay,az,radius": a is the vec3 at 0.
std::vector<CallArg> resolve(const Description& d) {
  const auto& names = ir::info(d.kind).params;
  auto at = [&](std::string_view n) -> long {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == n) return long(i);
    return -1;
  };
  std::vector<CallArg> out;
  std::string_view s = d.call_args;
  while (!s.empty()) {
    size_t c = s.find(',');
    std::string_view arg = s.substr(0, c);
    while (!arg.empty() && arg.front() == ' ') arg.remove_prefix(1);
    std::string a(arg);
    long i = at(a);
    if (i >= 0) {
      out.push_back({size_t(i), 1});
    } else {
      long x = at(a + "x");
      if (x < 0 || at(a + "y") != x + 1 || at(a + "z") != x + 2)
        throw std::logic_error(fmt::format("kind '{}': call argument '{}' names no parameter", ir::info(d.kind).name, a));
      out.push_back({size_t(x), 3});
    }
    if (c == std::string_view::npos) break;
    s.remove_prefix(c + 1);
  }
  return out;
}

}  // namespace

// A description missing a part is a compiler bug: say which kind.
void check(const Description& d) {
  const ir::KindInfo& k = ir::info(d.kind);
  auto missing = [&](const char* part) {
    throw std::logic_error(fmt::format("kind '{}': its description has no {}", k.name, part));
  };
  if (d.param_count != k.params.size())
    throw std::logic_error(fmt::format("kind '{}': its parameter struct holds {} numbers, its table row names {}",
                                       k.name, d.param_count, k.params.size()));
  if (d.child_props || d.evaluate || d.walk) {  // a kind with children
    if (!d.child_props) missing("child_props");
    if (!d.evaluate) missing("reference evaluate");
    if (!d.walk) missing("walk (its code in the scene walker)");
    if (d.dual_normals && !d.walk_dual) missing("walk_dual (it claims dual normals)");
    return;
  }
  if (d.yaml.empty()) missing("YAML key");
  if (d.example.empty()) missing("example");
  if (!d.lower) missing("lower");
  if (!d.props) missing("props");
  if (!d.distance) missing("reference distance");
  if (k.category == ir::Category::Fractal) {
    // A fractal writes its own code, orbit and estimator summary.
    if (!d.emit) missing("emit (its estimator's code)");
    if (!d.emit_orbit) missing("emit_orbit (its orbit trap and iteration count)");
    if (!d.orbit_colour) missing("reference orbit colour");
    if (!d.de_summary) missing("de_summary");
    if (d.dual_normals && !d.emit_dual) missing("emit_dual (it claims dual normals)");
  } else {
    if (k.stdlib_function.empty() || d.call_args.empty()) missing("stdlib call");
    if (d.dual_normals && d.gradient_function.empty()) missing("gradient function (it claims dual normals)");
  }
  // The node reference of docs/scene-format.md is generated from these.
  if (d.summary.empty()) missing("summary (docs)");
  if (d.docs.empty() && !k.params.empty()) missing("parameter docs");
  for (const ParamDoc& p : d.docs)
    if (p.name.empty() || p.type.empty() || p.what.empty())
      throw std::logic_error(fmt::format("kind '{}': parameter doc '{}' lacks its name, type or meaning", k.name, p.name));
}

namespace {

struct Registry {
  std::vector<const Description*> list, ops;
  std::map<ir::Kind, std::vector<CallArg>> args;
  Registry() {
#define DESCRIBED(e) list.push_back(&described::e);
#include "sdfc/kinds/described_kinds.def"
#undef DESCRIBED
    std::sort(list.begin(), list.end(), [](auto* a, auto* b) { return a->kind < b->kind; });
    for (const Description* d : list) {
      check(*d);
      if (!d->call_args.empty()) args[d->kind] = resolve(*d);
    }
    std::erase_if(list, [&](const Description* d) { return d->walk && (ops.push_back(d), true); });
  }
};

const Registry& registry() {
  static const Registry r;
  return r;
}

}  // namespace

const std::vector<const Description*>& all() { return registry().list; }

const Description* find(ir::Kind k) {
  for (const Description* d : all())
    if (d->kind == k) return d;
  return nullptr;
}

const std::vector<const Description*>& operations() { return registry().ops; }

const Description* operation(ir::Kind k) {
  for (const Description* d : operations())
    if (d->kind == k) return d;
  return nullptr;
}

// The first by kind id: `mandelbulb` is the Mandelbulb's key, whose
// lowering makes a Juliabulb when the scene gives `julia`.
const Description* find(std::string_view yaml) {
  for (const Description* d : all())
    if (d->yaml == yaml) return d;
  return nullptr;
}

const std::vector<CallArg>& call_args(ir::Kind k) { return registry().args.at(k); }

void Lowering::report(const frontend::MapReader& m, std::string_view key, const std::string& msg) {
  const SourceValue* v = m.get(key);
  r_.sink().error(v ? v->loc : body_.loc, msg, "");
}

void Lowering::fail(const frontend::MapReader& m, std::string_view key, const std::string& msg) {
  report(m, key, msg);
  failed_ = true;
}

ir::NodeId Lowering::make_animated(const std::vector<frontend::Param>& params) {
  if (failed_) return ir::kNoNode;
  return frontend::make_node(b_, d_.kind, params, {}, key_.loc);
}

ir::NodeId Lowering::make_node(std::vector<double> params) {
  if (failed_) return ir::kNoNode;
  return b_.make(d_.kind, std::move(params), {}, key_.loc);
}

}  // namespace sdfc::kinds
