// Legal but degenerate scenes (tests/stress_scenes/*.yaml: power 1, one
// iteration, tiny and huge objects, the camera inside geometry, march limits)
// render on the OpenCL device without a single NaN or Inf sample.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sdfrt/device.hpp>
#include <sdfrt/renderer.hpp>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> stress_scenes() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(SDFC_SOURCE_DIR) / "tests" / "stress_scenes"))
    if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

sdfrt::Device& device() {
  static sdfrt::Device d = sdfrt::open_device();
  return d;
}

class StressScene : public ::testing::TestWithParam<std::string> {};

TEST_P(StressScene, RendersWithoutNaNOrInf) {
  std::string path = std::string(SDFC_SOURCE_DIR) + "/tests/stress_scenes/" + GetParam() + ".yaml";
  // Odd sizes so SIMD padding lanes and edge tiles take part.
  SourceValue doc = load_scene_source(path, {"render.width=45", "render.height=29"});
  ir::Module m = build_module(doc, path);
  auto k = codegen::emit_opencl(m, {16, false});
  sdfrt::Renderer r(device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""});
  sdfrt::RenderOptions opt;
  opt.tile_width = opt.tile_height = 16;
  sdfrt::FloatImage img = r.render(codegen::frame_params(m.plan, 45, 29, 0.0), 45, 29, opt);
  long nonfinite = 0;
  for (float v : img.data) nonfinite += !std::isfinite(v);
  EXPECT_EQ(nonfinite, 0) << "NaN/Inf samples in " << GetParam();
  ASSERT_FALSE(img.data.empty());
}

INSTANTIATE_TEST_SUITE_P(All, StressScene, ::testing::ValuesIn(stress_scenes()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace sdfc::test
