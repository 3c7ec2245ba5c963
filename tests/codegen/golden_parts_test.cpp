// Golden parts of the compiler's output, each small enough that a change
// shows where it happened: the printed IR after every pass, and the scene
// part of the kernel (the generated scene functions, without the stdlib,
// shading and entry points around them). Regenerate with
//   SDFC_UPDATE_GOLDEN=1 ctest -R Golden
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "golden_file.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/ir/printer.hpp"

namespace sdfc {
namespace {

ir::Module compile_example(const std::string& example, const std::vector<std::string>& sets,
                           const passes::PassObserver& after = {}) {
  std::string src = std::string(SDFC_SOURCE_DIR) + "/examples/" + example;
  // The scene name in comments is the path relative to the repository.
  return build_module(load_scene_source(src, sets), "examples/" + example, after);
}

// The IR after each stage, in the form `sdfc compile --dump-after all` prints.
void expect_ir_golden(const std::string& example, const std::string& name) {
  std::string out;
  compile_example(example, {}, [&](std::string_view pass, const ir::Module& m) {
    out += fmt::format("// ---- IR after {} ({} nodes) ----\n{}", pass, ir::count_nodes(m), ir::print(m));
  });
  test::expect_golden(out, "ir/" + name + ".ir");
}

void expect_scene_golden(const std::string& example, const std::vector<std::string>& sets, bool aovs,
                         const std::string& name) {
  codegen::EmitOptions opt;
  opt.simd_width = 8;
  opt.aovs = aovs;
  std::string part = test::kernel_sections(codegen::emit_opencl(compile_example(example, sets), opt).source,
                                          test::scene_section_titles(), true);
  ASSERT_NE(part.find("scene_dist("), std::string::npos) << "no scene function found";
  test::expect_golden(part, "scene/" + name + ".w8.cl");
}

TEST(GoldenIr, Primitives) { expect_ir_golden("primitives.yaml", "primitives"); }
TEST(GoldenIr, Domain) { expect_ir_golden("domain.yaml", "domain"); }
TEST(GoldenIr, Blends) { expect_ir_golden("blends.yaml", "blends"); }
TEST(GoldenIr, FractalZoo) { expect_ir_golden("fractal-zoo.yaml", "fractal-zoo"); }
TEST(GoldenIr, Animated) { expect_ir_golden("animated.yaml", "animated"); }

TEST(GoldenScene, Primitives) { expect_scene_golden("primitives.yaml", {}, false, "primitives"); }
TEST(GoldenScene, Domain) { expect_scene_golden("domain.yaml", {}, false, "domain"); }
TEST(GoldenScene, BlendsMixMaterials) { expect_scene_golden("blends.yaml", {}, false, "blends"); }
TEST(GoldenScene, HybridOrbitTrap) { expect_scene_golden("hybrid.yaml", {}, false, "hybrid"); }
TEST(GoldenScene, FractalZooWithAovs) { expect_scene_golden("fractal-zoo.yaml", {}, true, "fractal-zoo"); }
TEST(GoldenScene, Animated) { expect_scene_golden("animated.yaml", {}, false, "animated"); }
TEST(GoldenScene, MandelbulbDualNormals) {
  expect_scene_golden("mandelbulb.yaml", {"render.normals=dual"}, false, "mandelbulb-dual");
}

}  // namespace
}  // namespace sdfc
