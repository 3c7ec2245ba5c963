#include "sdfc/source/unlock.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "sdfc/kinds/param_range.hpp"

namespace sdfc {

namespace {

// "a.b[2].c" -> a, b, 2, c; "a.b.2.c" splits the same way.
std::vector<std::string> steps(const std::string& path) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : path) {
    if (c == '.' || c == '[' || c == ']') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

SourceValue* walk(SourceValue& root, const std::string& path) {
  SourceValue* cur = &root;
  for (const auto& step : steps(path)) {
    if (cur->is_seq()) {
      if (step.empty() || step.size() > 8 || step.find_first_not_of("0123456789") != std::string::npos) return nullptr;
      size_t i = std::stoul(step);
      if (i >= cur->items.size()) return nullptr;
      cur = &cur->items[i];
    } else if (cur->is_map()) {
      cur = cur->find(step);
      if (!cur) return nullptr;
    } else {
      return nullptr;
    }
  }
  return cur;
}

bool parse_double(const std::string& s, double* out) {
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size();
}

// No range asked for: a described kind's parameter spans its documented range.
void documented_range(UnlockSlot& s, const SourceValue& v) {
  const kinds::ParamDoc* doc = kinds::documented_param(steps(s.path));
  std::optional<kinds::DocRange> r = doc ? kinds::parse_doc_range(doc->range) : std::nullopt;
  double x = 0;
  if (!r || !parse_double(v.scalar, &x)) return;
  std::tie(s.lo, s.hi) = kinds::slider_range(*r, x);
  s.ranged = true;
}

SourceLoc where(const std::string& text) { return SourceLoc(std::make_shared<const std::string>("--unlock " + text), 0, 0); }

}  // namespace

UnlockRequest parse_unlock(const std::string& text) {
  UnlockRequest r;
  size_t eq = text.find('=');
  r.path = text.substr(0, eq);
  if (r.path.empty()) fail(where(text), "expected --unlock PATH or PATH=LO:HI", "e.g. --unlock lights[0].intensity=0:4");
  if (eq == std::string::npos) return r;
  std::string range = text.substr(eq + 1);
  size_t colon = range.find(':');
  double lo = 0, hi = 0;
  if (colon == std::string::npos || !parse_double(range.substr(0, colon), &lo) ||
      !parse_double(range.substr(colon + 1), &hi) || !(lo <= hi))
    fail(where(text), fmt::format("expected a range LO:HI with LO <= HI after '=', got '{}'", range), "e.g. =0.5:2");
  r.range = std::make_pair(lo, hi);
  return r;
}

const SourceValue* find_value(const SourceValue& root, const std::string& path) {
  return walk(const_cast<SourceValue&>(root), path);
}

UnlockSlots mark_unlocked(SourceValue& root, const std::vector<UnlockRequest>& requests) {
  UnlockSlots slots;
  for (const auto& rq : requests) {
    SourceValue* v = walk(root, rq.path);
    if (!v) fail(root.loc, fmt::format("--unlock {}: the scene has no value at this path", rq.path),
                 "a path walks maps by key and lists by index, e.g. scene.union[1].sphere.radius");
    if (!v->is_scalar()) fail(v->loc, fmt::format("--unlock {}: expected a number here, got {}", rq.path, v->kind_name()),
                              v->is_seq() ? "unlock the list's items one by one, e.g. " + rq.path + "[0]" : "");
    if (v->unlock) fail(v->loc, fmt::format("--unlock {}: this value is unlocked twice", rq.path), "");
    auto s = std::make_shared<UnlockSlot>();
    s->index = static_cast<int>(slots.size());
    s->path = rq.path;
    if (rq.range) s->ranged = true, s->lo = rq.range->first, s->hi = rq.range->second;
    else documented_range(*s, *v);
    v->unlock = s;
    slots.push_back(s);
  }
  return slots;
}

UnlockSlots marked_slots(const SourceValue& root) {
  UnlockSlots out;
  auto visit = [&](auto& self, const SourceValue& v) -> void {
    if (v.unlock) out.push_back(v.unlock);
    for (const auto& i : v.items) self(self, i);
    for (const auto& [k, e] : v.entries) self(self, e);
  };
  visit(visit, root);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a->index < b->index; });
  out.erase(std::unique(out.begin(), out.end()), out.end());  // a subtree used twice holds its slots twice
  return out;
}

void check_unlocked(const SourceValue& root, const UnlockSlots& slots) {
  DiagnosticSink sink;
  for (const auto& s : slots) {
    if (s->taken) continue;
    const SourceValue* v = find_value(root, s->path);
    sink.error(v ? v->loc : root.loc,
               fmt::format("{} cannot be unlocked: it is baked into the kernel's code (a count, a choice, or a value "
                           "that cannot be animated), so changing it needs a rebuild",
                           s->path),
               "only the values listed under 'Animation' in docs/scene-format.md can change without a rebuild");
  }
  sink.throw_if_any();
}

std::vector<float> unlocked_values(const UnlockSlots& slots) {
  std::vector<float> out;
  for (const auto& s : slots) out.push_back(static_cast<float>(s->value));
  return out;
}

}  // namespace sdfc
