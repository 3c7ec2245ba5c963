// The docs half of each kind description: every described kind is
// documented, and every documented default is what the reader really uses
// when the parameter is left out (so the node reference of
// docs/scene-format.md, generated from these docs, cannot drift).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "scene_text.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/kinds/registry.hpp"

namespace sdfc {
namespace {

// A parsed value back in YAML flow style.
std::string flow(const SourceValue& v) {
  switch (v.kind) {
    case SourceValue::Kind::Null: return "null";
    case SourceValue::Kind::Scalar: {
      if (!v.quoted) return v.scalar;
      std::string out = "\"";
      for (char c : v.scalar) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
      return out + "\"";
    }
    case SourceValue::Kind::Sequence: {
      std::string out = "[";
      for (size_t i = 0; i < v.items.size(); ++i) out += (i ? ", " : "") + flow(v.items[i]);
      return out + "]";
    }
    case SourceValue::Kind::Map: {
      std::string out = "{";
      for (size_t i = 0; i < v.entries.size(); ++i)
        out += (i ? ", " : "") + flow(v.entries[i].first) + ": " + flow(v.entries[i].second);
      return out + "}";
    }
  }
  return "";
}

// The example node with `key` of its kind's body left out (fallback empty)
// or written as `fallback`.
std::string example_with(const kinds::Description& d, const kinds::ParamDoc& p, std::string_view fallback) {
  SourceValue node = load_yaml_text(std::string(d.example), "example.yaml");
  SourceValue* body = node.find(d.yaml);
  std::string out = "{";
  for (size_t i = 0; i < node.entries.size(); ++i) {
    out += (i ? ", " : "") + flow(node.entries[i].first) + ": ";
    if (&node.entries[i].second != body) {
      out += flow(node.entries[i].second);
      continue;
    }
    std::string inner;
    for (const auto& [k, v] : body->entries)
      if (k.scalar != p.name) inner += (inner.empty() ? "" : ", ") + k.scalar + ": " + flow(v);
    if (!fallback.empty()) inner += (inner.empty() ? "" : ", ") + std::string(p.name) + ": " + std::string(fallback);
    out += "{" + inner + "}";
  }
  return out + "}";
}

std::string lowered(const std::string& node) {
  ir::Module m = test::lower_text("scene: " + node + "\n");
  return ir::print(m, {.props = false, .plan = false});
}

TEST(KindDocs, EveryDescribedKindIsDocumented) {
  for (const kinds::Description* d : kinds::all()) {
    SCOPED_TRACE(std::string(d->yaml));
    EXPECT_FALSE(d->summary.empty());
    std::set<std::string_view> names;
    for (const kinds::ParamDoc& p : d->docs) {
      EXPECT_TRUE(names.insert(p.name).second) << "parameter '" << p.name << "' documented twice";
      EXPECT_FALSE(p.type.empty()) << p.name;
      EXPECT_FALSE(p.what.empty()) << p.name;
    }
  }
}

// Primitives, fractals and the operations whose example writes them under
// their own key with a map (twist, polar_repeat, smooth_union, ...).
TEST(KindDocs, DocumentedDefaultsAreTheReadersDefaults) {
  int checked = 0;
  std::vector<const kinds::Description*> described = kinds::all();
  for (const kinds::Description* d : kinds::operations())
    if (!d->example.empty()) described.push_back(d);
  for (const kinds::Description* d : described) {
    SourceValue node = load_yaml_text(std::string(d->example), "example.yaml");
    const SourceValue* body = node.find(d->yaml);
    const bool operation = kinds::operation(d->kind) != nullptr;
    if (operation && !body) continue;  // written under other keys (chamfer_union, ...)
    ASSERT_NE(body, nullptr) << d->yaml << ": the example does not hold its own key";
    if (!body->is_map()) continue;  // a list of children or a scalar: no named parameters
    for (const kinds::ParamDoc& p : d->docs) {
      if (p.fallback.empty() || p.fallback[0] == '(') continue;  // required, or a default said in words
      std::string left_out = example_with(*d, p, ""), written = example_with(*d, p, p.fallback);
      SCOPED_TRACE(std::string(d->yaml) + "." + std::string(p.name) + ": " + left_out + " vs " + written);
      auto errors = test::errors_of("scene: " + written + "\n");
      ASSERT_TRUE(errors.empty()) << "the documented default is refused: " << errors[0].message;
      errors = test::errors_of("scene: " + left_out + "\n");
      ASSERT_TRUE(errors.empty()) << "leaving the parameter out is refused: " << errors[0].message;
      EXPECT_EQ(lowered(left_out), lowered(written)) << "the reader's default is not the documented `" << p.fallback
                                                     << "`";
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace sdfc
