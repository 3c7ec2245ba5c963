// The kinds with children (transforms, domain operations, combinators) are
// descriptions too: every kind of the table has one, each is whole, and
// the passes and emitters that used to switch over them follow the hooks.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "scene_text.hpp"
#include "sdfc/ir/dual_normals.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

TEST(KindOperations, EveryKindOfTheTableIsDescribed) {
  for (const ir::KindInfo& k : ir::all_kinds()) {
    const bool leaf = kinds::find(k.kind) != nullptr, op = kinds::operation(k.kind) != nullptr;
    EXPECT_TRUE(leaf != op) << k.name << (leaf ? " is described twice" : " has no description");
    // A node with children is an operation; a leaf is a primitive or fractal.
    // An object set holds its children as data, and the walker writes it.
    EXPECT_EQ(op, k.arity != 0 || k.kind == ir::Kind::ObjectSet) << k.name;
  }
  for (const kinds::Description* d : kinds::operations()) EXPECT_EQ(kinds::operation(d->kind), d);
}

// A description without one of its hooks fails the start-up check with the
// kind's name.
TEST(KindOperations, AnOperationWithoutAHookFailsNamingIt) {
  ASSERT_GE(kinds::operations().size(), 27u);  // 3 transforms, step_factor, material, bounded, 12 domain operations, 9 combinators
  for (const kinds::Description* d : kinds::operations()) {
    const std::string name(ir::info(d->kind).name);
    EXPECT_NO_THROW(kinds::check(*d)) << name;
    for (auto drop : {+[](kinds::Description& b) { b.child_props = nullptr; },
                      +[](kinds::Description& b) { b.evaluate = nullptr; },
                      +[](kinds::Description& b) { b.walk = nullptr; },
                      +[](kinds::Description& b) { b.dual_normals = true, b.walk_dual = nullptr; }}) {
      kinds::Description broken = *d;
      drop(broken);
      try {
        kinds::check(broken);
        ADD_FAILURE() << name << ": a missing hook passed the check";
      } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("kind '" + name + "'"), std::string::npos) << e.what();
      }
    }
  }
}

// Every operation a scene writes has its entry in the node reference: an
// example that lowers to a node of its kind, a summary and its parameters.
// The compiler makes bounded and object_set itself; material nodes come
// from the `materials` section, which has its own docs.
TEST(KindOperations, EveryWrittenOperationHasAnExampleOfItsKind) {
  int documented = 0;
  for (const kinds::Description* d : kinds::operations()) {
    const std::string name(ir::info(d->kind).name);
    if (d->kind == ir::Kind::Bounded || d->kind == ir::Kind::ObjectSet || d->kind == ir::Kind::Material) {
      EXPECT_TRUE(d->example.empty()) << name << " is not written by scenes";
      continue;
    }
    ASSERT_FALSE(d->example.empty()) << name << " has no example";
    EXPECT_FALSE(d->summary.empty()) << name;
    EXPECT_FALSE(d->docs.empty()) << name;
    ir::Module m = test::lower_text("scene: " + std::string(d->example) + "\n");
    bool found = false;
    for (ir::NodeId id : m.graph->postorder(m.root)) found = found || m.graph->node(id).kind == d->kind;
    EXPECT_TRUE(found) << name << "'s example has no " << name << " node: " << d->example;
    ++documented;
  }
  EXPECT_EQ(documented, int(kinds::operations().size()) - 3);
}

// render.normals: dual accepts exactly the operations that can write their gradient.
TEST(KindOperations, DualNormalsFollowTheDescriptions) {
  int dual = 0;
  for (const kinds::Description* d : kinds::operations()) {
    EXPECT_EQ(ir::supports_dual_normals(d->kind), d->walk_dual != nullptr) << ir::info(d->kind).name;
    dual += d->walk_dual != nullptr;
  }
  EXPECT_EQ(dual, 12);  // translate, rotate, scale, step_factor, material, bounded and the six unions/intersections/differences
}

// The fold hooks: identities vanish, nested translations add up, a
// one-child union is its child.
std::vector<const ir::Node*> nodes_of(const ir::Module& m, ir::Kind k) {
  std::vector<const ir::Node*> out;
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (m.graph->node(id).kind == k) out.push_back(&m.graph->node(id));
  return out;
}

TEST(KindOperations, FoldHooksSimplify) {
  ir::Module a = passes::fold_constants(test::lower_text("scene: {sphere: {radius: 1}, translate: [0, 0, 0], scale: 1}\n"));
  EXPECT_TRUE(nodes_of(a, ir::Kind::Translate).empty());
  EXPECT_TRUE(nodes_of(a, ir::Kind::Scale).empty());
  ir::Module b = passes::fold_constants(test::lower_text(
      "scene: {union: [{union: [{sphere: {radius: 1}}], translate: [1, 0, 0]}], translate: [0, 2, 0]}\n"));
  EXPECT_TRUE(nodes_of(b, ir::Kind::Union).empty());
  auto t = nodes_of(b, ir::Kind::Translate);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0]->params, (std::vector<double>{1, 2, 0}));
}

}  // namespace
}  // namespace sdfc
