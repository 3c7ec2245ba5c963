// The IR's printed form (golden strings) and hash-consing.
#include <gtest/gtest.h>

#include "scene_text.hpp"
#include "sdfc/ir/printer.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

std::string geometry_of(const std::string& scene, bool optimise) {
  ir::Module m = test::lower_text(scene);
  if (optimise) m = passes::run_pipeline(std::move(m));
  return ir::print(m, {.props = false, .plan = false});
}

TEST(IrPrinter, GoldenAsWritten) {
  const char* scene =
      "scene:\n"
      "  union:\n"
      "    - sphere: {radius: 1}\n"
      "      translate: [0, 0, 1]\n"
      "    - box: {size: [2, 2, 0.5], radius: 0.1}\n"
      "      scale: 2\n";
  EXPECT_EQ(geometry_of(scene, false),
            "%0 = sphere radius=1\n"
            "%1 = translate x=0 y=0 z=1 %0\n"
            "%2 = box hx=1 hy=1 hz=0.25 radius=0.1\n"
            "%3 = scale s=2 %2\n"
            "%4 = union %1 %3\n"
            "root = %4\n");
}

TEST(IrPrinter, PropsAfterInference) {
  ir::Module m = passes::run_pipeline(test::lower_text("scene: {sphere: {radius: 2}, translate: [1, 0, 0]}\n"));
  EXPECT_EQ(ir::print(m, {.props = true, .plan = false}),
            "%0 = sphere radius=2    ; exact L=1 cost=6 bounds=[-2 -2 -2 .. 2 2 2]\n"
            "%1 = translate x=1 y=0 z=0 %0    ; exact L=1 cost=9 bounds=[-1 -2 -2 .. 3 2 2]\n"
            "root = %1\n");
}

TEST(IrPrinter, PlanIsPrinted) {
  ir::Module m = test::lower_text("camera: {fov: 30}\nscene: {sphere: {radius: 1}}\n");
  std::string s = ir::print(m);
  EXPECT_NE(s.find("camera position=[0, -3, 0] target=[0, 0, 0] up=[0, 0, 1] fov=30"), std::string::npos) << s;
  EXPECT_NE(s.find("material 0 'default'"), std::string::npos) << s;
}

TEST(HashConsing, IdenticalSubtreesAreOneNode) {
  // Two identical translated spheres and a third elsewhere: the sphere leaf is
  // shared by all three, the first two translates are the same node.
  ir::Module m = test::lower_text(
      "scene:\n  union:\n"
      "    - {sphere: {radius: 1}, translate: [1, 0, 0]}\n"
      "    - {sphere: {radius: 1}, translate: [1, 0, 0]}\n"
      "    - {sphere: {radius: 1}, translate: [0, 1, 0]}\n");
  EXPECT_EQ(ir::count_nodes(m), 4u);  // sphere, 2 translates, union
  EXPECT_EQ(m.graph->size(), 4u);     // nothing was created twice
  const ir::Node& u = m.graph->node(m.root);
  ASSERT_EQ(u.children.size(), 3u);
  EXPECT_EQ(u.children[0], u.children[1]);
  EXPECT_NE(u.children[0], u.children[2]);
}

TEST(HashConsing, NegativeZeroIsZero) {
  ir::Graph g;
  ir::Builder b(g);
  EXPECT_EQ(b.make(ir::Kind::Sphere, {0.0}, {}), b.make(ir::Kind::Sphere, {-0.0}, {}));
  EXPECT_NE(b.make(ir::Kind::Sphere, {1.0}, {}), b.make(ir::Kind::Sphere, {2.0}, {}));
}

}  // namespace
}  // namespace sdfc
