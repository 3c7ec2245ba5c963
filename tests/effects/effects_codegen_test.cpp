// Each effect's code reaches the kernel only when the scene turns it on.
#include <gtest/gtest.h>

#include <algorithm>

#include "render_helpers.hpp"
#include "sdfc/codegen/emit_opencl.hpp"

namespace sdfc {
namespace {

std::string kernel_of(const std::string& scene) { return codegen::emit_opencl(test::compile_text(scene), {16, false}).source; }
bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

const char* kPlain = "lights:\n  - directional: {direction: [0, 0, -1]}\nscene:\n  union:\n    - plane: {}\n    - sphere: {radius: 1}\n";

// Names that only effects bring into a kernel.
const char* kEffectMarks[] = {"shadow_hard", "shadow_soft", "ao_normal_samples", "ao_step_count", "occlusion",
                              "march_sphere_trace_closest", "glow", "fog_", "fresnel_schlick", "material_reflectivity",
                              "tonemap_", "fx_hash", "fx_tent", "s_first", "lens", "focus", "jitter * "};

TEST(EffectsCodegen, NoEffectCodeWithoutEffects) {
  std::string k = kernel_of(kPlain);
  for (const char* mark : kEffectMarks) EXPECT_FALSE(has(k, mark)) << mark;
}

TEST(EffectsCodegen, EachEffectBringsOnlyItsCode) {
  struct Case {
    std::string yaml;
    std::vector<std::string> marks;  // exactly the kEffectMarks this effect brings
  };
  const std::string scene = "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 1}\n";
  std::vector<Case> cases = {
      {"lights:\n  - directional: {direction: [0, 0, -1], shadows: hard}\n", {"shadow_hard"}},
      {"lights:\n  - point: {position: [0, 0, 3], shadows: soft, softness: 8}\n", {"shadow_soft"}},
      {"effects: {ambient_occlusion: {}}\n", {"ao_normal_samples", "occlusion"}},
      {"effects: {ambient_occlusion: {method: step_count}}\n", {"ao_step_count", "occlusion"}},
      {"effects: {glow: {}}\n", {"march_sphere_trace_closest", "glow"}},
      {"effects: {fog: {}}\n", {"fog_"}},
      {"effects: {fog: {height_falloff: 0.5}}\n", {"fog_"}},
      {"effects: {reflections: {depth: 2}}\n", {"fresnel_schlick", "material_reflectivity"}},
      {"render: {tone_mapping: aces}\n", {"tonemap_"}},
      {"render: {samples: 4, filter: tent}\n", {"fx_hash", "fx_tent", "s_first"}},
      {"render: {dither: true}\n", {"fx_hash", "jitter * "}},
      {"camera: {position: [0, -5, 1], target: [0, 0, 0], aperture: 0.1}\n", {"fx_hash", "s_first", "lens", "focus"}},
  };
  for (const auto& c : cases) {
    std::string k = kernel_of(c.yaml + scene);
    for (const char* mark : kEffectMarks) {
      bool wanted = std::find(c.marks.begin(), c.marks.end(), mark) != c.marks.end();
      EXPECT_EQ(has(k, mark), wanted) << c.yaml << (wanted ? " lacks " : " has ") << mark;
    }
  }
  EXPECT_TRUE(has(kernel_of("effects: {fog: {height_falloff: 0.5}}\n" + scene), "fog_height("));
}

TEST(EffectsCodegen, BadEffectSettingsAreLocated) {
  try {
    test::compile_text("effects: {fog: {densty: 0.1}}\nscene: {sphere: {}}\n");
    FAIL() << "accepted a misspelt key";
  } catch (const SceneError& e) {
    std::string msg = e.what();
    EXPECT_TRUE(has(msg, "t.yaml:1")) << msg;
    EXPECT_TRUE(has(msg, "density")) << msg;  // did you mean
  }
  try {
    test::compile_text("lights:\n  - directional: {shadows: sofft}\nscene: {sphere: {}}\n");
    FAIL() << "accepted a bad shadow kind";
  } catch (const SceneError& e) {
    EXPECT_TRUE(has(e.what(), "soft")) << e.what();
  }
}

}  // namespace
}  // namespace sdfc
