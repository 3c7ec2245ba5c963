// The path integrator's code reaches a kernel only when the scene asks for
// it, and each of its parts (glossy lobe, emission, firefly clamp) only when
// a material or setting uses it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "render_helpers.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc {
namespace {

std::string kernel_of(const std::string& scene, int width = 16) {
  return codegen::emit_opencl(test::compile_text(scene), {width, false}).source;
}
bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

// Names only the path integrator brings into a kernel.
const char* kPathMarks[] = {"sdfc_path", "path_rand", "path_cosine_dir", "path_glossy_eval", "path_ggx", "path_surface",
                            "emission", "path_firefly", "roulette", "march_signed", "glass_fresnel", "glass_absorb"};

const std::string kScene = "lights:\n  - directional: {direction: [0, 0, -1], shadows: soft}\nscene:\n  union:\n"
                           "    - plane: {}\n    - sphere: {radius: 1}\n      material: m\n";

TEST(PathCodegen, DirectKernelsHaveNoPathCode) {
  // every example scene, as it is (the direct integrator is the default)
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(SDFC_SOURCE_DIR) / "examples")) {
    if (e.path().extension() != ".yaml") continue;
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    std::string k = kernel_of(text.str());
    for (const char* mark : kPathMarks) EXPECT_FALSE(has(k, mark)) << e.path() << " has " << mark;
    ++n;
  }
  EXPECT_GT(n, 5);
  // materials with path-only keys leave a direct kernel as it was
  std::string plain = kernel_of("materials: {m: {color: [0.5, 0.5, 0.5]}}\n" + kScene);
  EXPECT_EQ(kernel_of("materials: {m: {color: [0.5, 0.5, 0.5], roughness: 0.2, metalness: 1, emission: [1, 0, 0]}}\n" + kScene),
            plain);
  EXPECT_EQ(kernel_of("materials: {m: {color: [0.5, 0.5, 0.5], glass: {ior: 1.4, absorption: [1, 0, 0]}}}\n" + kScene), plain);
  EXPECT_TRUE(kernel_of("render: {integrator: direct, max_bounces: 9, firefly_clamp: 4}\nmaterials: {m: {color: [0.5, 0.5, 0.5]}}\n" + kScene) ==
              kernel_of("render: {width: 1280}\nmaterials: {m: {color: [0.5, 0.5, 0.5]}}\n" + kScene));
}

TEST(PathCodegen, EachPartOnlyWhenUsed) {
  struct Case {
    std::string yaml;
    std::vector<std::string> marks;  // exactly the kPathMarks this scene brings
  };
  const std::vector<std::string> base = {"sdfc_path", "path_rand", "path_cosine_dir", "roulette"};
  auto with = [&](std::vector<std::string> more) {
    more.insert(more.end(), base.begin(), base.end());
    return more;
  };
  std::vector<Case> cases = {
      {"render: {integrator: path}\nmaterials: {m: {color: [0.5, 0.5, 0.5]}}\n", base},
      {"render: {integrator: path}\nmaterials: {m: {roughness: 0.3}}\n", with({"path_glossy_eval", "path_ggx", "path_surface"})},
      {"render: {integrator: path}\nmaterials: {m: {metalness: 1}}\n", with({"path_glossy_eval", "path_ggx", "path_surface"})},
      {"render: {integrator: path}\nmaterials: {m: {emission: [2, 1, 0]}}\n", with({"path_surface", "emission"})},
      {"render: {integrator: path, firefly_clamp: 5}\nmaterials: {m: {}}\n", with({"path_firefly"})},
      {"render: {integrator: path}\nmaterials: {m: {glass: {ior: 1.33}}}\n",
       with({"path_surface", "march_signed", "glass_fresnel", "glass_absorb"})},
  };
  for (const auto& c : cases) {
    for (int width : {1, 16}) {
      std::string k = kernel_of(c.yaml + kScene, width);
      for (const char* mark : kPathMarks) {
        bool wanted = std::find(c.marks.begin(), c.marks.end(), mark) != c.marks.end();
        EXPECT_EQ(has(k, mark), wanted) << c.yaml << (wanted ? " lacks " : " has ") << mark;
      }
      // the path integrator replaces the direct one's shading
      EXPECT_FALSE(has(k, "shade_surface")) << c.yaml;
      EXPECT_FALSE(has(k, "sdfc_radiance")) << c.yaml;
    }
  }
}

// background.sky brings shade_sky and a sun (a directional light with hard
// shadows) to either integrator; a gradient background neither.
TEST(PathCodegen, SkyOnlyWhenUsed) {
  const std::string scene = "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 1}\n";
  for (const char* integrator : {"direct", "path"}) {
    std::string render = std::string("render: {integrator: ") + integrator + "}\n";
    std::string plain = kernel_of(render + scene);
    EXPECT_FALSE(has(plain, "shade_sky")) << integrator;
    std::string sky = kernel_of(render + "background: {sky: {sun_direction: [0.3, -0.4, 0.5], turbidity: 4}}\n" + scene);
    EXPECT_TRUE(has(sky, "shade_sky(rd, ")) << integrator;
    EXPECT_FALSE(has(sky, "shade_background")) << integrator;
    EXPECT_TRUE(has(sky, "shadow_hard")) << integrator << ": the sun casts shadows";
  }
  // the sun replaces the default key light; a set sun does not shine
  auto lights = [](const std::string& yaml) {
    int n = 0;
    for (const auto& l : test::compile_text(yaml).plan.lights) n += l.kind == ir::LightKind::Directional;
    return n;
  };
  EXPECT_EQ(lights("background: {sky: {sun_direction: [0, 0.5, 1]}}\n" + scene), 1);
  EXPECT_EQ(lights("background: {sky: {sun_direction: [0, 1, -0.5]}}\n" + scene), 0);
  EXPECT_EQ(lights("background: {sky: {}}\nlights:\n  - directional: {direction: [0, 0, -1]}\n" + scene), 2);
}

TEST(PathCodegen, BadSettingsAreLocated) {
  for (const char* bad : {"render: {integrator: paths}\n", "render: {integrator: path, max_bounces: 0}\n",
                          "render: {firefly_clamp: -1}\n", "materials: {m: {roughness: 2}}\n",
                          "materials: {m: {emission: [1, 1]}}\n", "background: {sky: {turbidity: 20}}\n",
                          "background: {sky: {sun_direction: [0, 0, 0]}}\n", "background: {sky: {sun: 1}}\n",
                          "materials: {m: {glass: {ior: 0.5}}}\n", "materials: {m: {glass: {}, roughness: 0.1}}\n",
                          "materials: {m: {glass: {absorption: [1, 1, 1], color: [1, 1, 1]}}}\n",
                          "materials: {m: {glass: {distance: 2}}}\n", "materials: {m: {glass: 1}}\n",
                          "materials: {m: {glass: {ior: 1.5, tint: [1, 0, 0]}}}\n"}) {
    try {
      test::compile_text(std::string(bad) + "scene: {sphere: {}}\n");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const SceneError& e) {
      EXPECT_GE(e.diagnostics().front().loc.line, 1) << bad;
    }
  }
}

}  // namespace
}  // namespace sdfc
