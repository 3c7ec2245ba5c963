// The kind descriptions (compiler/src/kinds/): every one is whole, its
// example scene builds, and what it says agrees with the table row and the
// stdlib. A new kind is tested here, and by the suites that iterate
// kinds::all(), without a line of test code.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "scene_text.hpp"
#include "sdfc/codegen/stdlib_manifest.hpp"
#include "sdfc/ir/dual_normals.hpp"
#include "sdfc/kinds/registry.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

TEST(KindTable, EveryDescriptionIsWhole) {
  // The registry checks each description on first use and throws naming the kind.
  ASSERT_NO_THROW(kinds::all());
  ASSERT_FALSE(kinds::all().empty());
  for (const kinds::Description* d : kinds::all()) {
    EXPECT_EQ(kinds::find(d->kind), d);
    // The Juliabulb is written `mandelbulb` (with julia:): the key finds the Mandelbulb.
    if (d->kind != ir::Kind::Juliabulb) {
      EXPECT_EQ(kinds::find(d->yaml), d) << d->yaml;
    }
    EXPECT_FALSE(d->example.empty()) << ir::info(d->kind).name << " has no example scene";
  }
}

TEST(KindTable, EveryPrimitiveAndFractalIsDescribed) {
  for (const ir::KindInfo& k : ir::all_kinds()) {
    if (k.category == ir::Category::Primitive || k.category == ir::Category::Fractal) {
      EXPECT_NE(kinds::find(k.kind), nullptr) << k.name << " has no description";
    }
  }
}

// A fractal writes its own code: a description without one of its hooks
// fails the start-up check with the kind's name and the missing part.
TEST(KindTable, AFractalWithoutAHookFailsNamingIt) {
  int fractals = 0;
  for (const kinds::Description* d : kinds::all()) {
    const ir::KindInfo& info = ir::info(d->kind);
    if (info.category != ir::Category::Fractal) continue;
    ++fractals;
    EXPECT_NO_THROW(kinds::check(*d));
    for (auto drop : {+[](kinds::Description& b) { b.emit = nullptr; }, +[](kinds::Description& b) { b.emit_orbit = nullptr; },
                      +[](kinds::Description& b) { b.orbit_colour = nullptr; }}) {
      kinds::Description broken = *d;
      drop(broken);
      try {
        kinds::check(broken);
        ADD_FAILURE() << info.name << ": a missing hook passed the check";
      } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("kind '" + std::string(info.name) + "'"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_EQ(fractals, 9);  // mandelbulb, its julia form, mandelbox, julia, menger, sierpinski, kifs, hybrid, formula
}

const ir::Node& find_kind(const ir::Graph& g, ir::NodeId root, ir::Kind k) {
  for (ir::NodeId id : g.postorder(root))
    if (g.node(id).kind == k) return g.node(id);
  static const ir::Node none{};
  return none;
}

TEST(KindTable, ExamplesBuildAndAgreeWithTheStdlib) {
  const auto& manifest = codegen::StdlibManifest::instance();
  for (const kinds::Description* d : kinds::all()) {
    const ir::KindInfo& info = ir::info(d->kind);
    SCOPED_TRACE(std::string(info.name));
    auto errors = test::errors_of("scene: " + std::string(d->example) + "\n");
    ASSERT_TRUE(errors.empty()) << errors[0].message;
    ir::Module m = passes::run_pipeline(test::lower_text("scene: " + std::string(d->example) + "\n"));
    const ir::Node& n = find_kind(*m.graph, m.root, d->kind);
    ASSERT_EQ(n.kind, d->kind) << "the example holds no " << info.name;
    EXPECT_FALSE(n.props.bounds.empty());
    EXPECT_EQ(ir::supports_dual_normals(d->kind), d->dual_normals);
    // A fractal writes its own code (hybrid: an inline orbit); a primitive
    // calls its stdlib function, whose class tag says what the props say.
    if (info.category == ir::Category::Fractal) {
      EXPECT_NE(d->emit, nullptr);
      continue;
    }
    const codegen::StdlibFunction* fn = manifest.find(info.stdlib_function);
    ASSERT_NE(fn, nullptr) << info.stdlib_function;
    EXPECT_EQ(fn->cls, std::string(ir::to_string(n.props.cls)));
  }
}

}  // namespace
}  // namespace sdfc
