// background.map: an equirectangular environment map lighting the path
// integrator, on PoCL. A constant map is the plain background of its colour,
// importance sampling beats uniform sampling at equal samples, a rotation
// moves the map where the frame's maths puts it, and bad files are located.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "env_map_files.hpp"
#include "render_helpers.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/codegen/kernel_abi.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "test_files.hpp"

namespace sdfc {
namespace {

using test::render_text;

double mean_rgb(const sdfrt::FloatImage& img, bool covered_only) {
  const int hit = abi::plane_index("hit");
  double sum = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (covered_only && img.at(hit, x, y) < 1.0f) continue;
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(img.at(c, x, y))) << x << "," << y;
        sum += img.at(c, x, y);
      }
      ++n;
    }
  return n ? sum / (3.0 * n) : 0;
}

// A diffuse ball of albedo 0.5 (no lights) under `background`.
std::string ball(const std::string& background, int samples) {
  return fmt::format(
      "camera: {{position: [0, -4, 0], target: [0, 0, 0], fov: 30}}\n"
      "render: {{width: 24, height: 24, samples: {}, gamma: 1, integrator: path, max_bounces: 8}}\n"
      "background: {}\nlights: []\n"
      "materials:\n  m: {{color: [0.5, 0.5, 0.5]}}\n"
      "scene: {{sphere: {{radius: 1}}, material: m}}\n",
      samples, background);
}

auto constant(float v) {
  return [v](int, int) { return std::array<float, 3>{v, v, v}; };
}

// A constant map lights like the plain background of its colour: the
// furnace converges to 0.5 x 0.75, and camera rays see 0.75 (from .exr and
// .hdr, at 16 lanes and at one).
TEST(PathEnvMap, ConstantMapIsThePlainBackground) {
  test::TempDir dir;
  const std::string exr = (dir.path() / "grey.exr").string(), hdr = (dir.path() / "grey.hdr").string();
  test::write_exr_map(exr, 32, 16, constant(0.75f));
  test::write_hdr_map(hdr, 32, 16, constant(0.75f));
  const double plain = mean_rgb(render_text(ball("[0.75, 0.75, 0.75]", 256)).image, true);
  for (const std::string& file : {exr, hdr})
    for (int width : {16, 1}) {
      auto r = render_text(ball("{map: '" + file + "'}", 256), width);
      const double lit = mean_rgb(r.image, true);
      EXPECT_NEAR(lit, 0.375, 0.375 * 0.01) << file << " width " << width;
      EXPECT_NEAR(lit, plain, 0.004) << file << " width " << width;
      EXPECT_NEAR(r.image.at(0, 0, 0), 0.75, 1e-5);  // the camera sees the map
    }
}

// With visible: false camera rays see the top/bottom gradient; paths still
// take their light from the map.
TEST(PathEnvMap, HiddenMapShowsTheGradient) {
  test::TempDir dir;
  const std::string exr = (dir.path() / "grey.exr").string();
  test::write_exr_map(exr, 32, 16, constant(0.75f));
  auto r = render_text(ball("{map: '" + exr + "', visible: false, top: [0.1, 0.2, 0.3], bottom: [0.1, 0.2, 0.3]}", 128));
  EXPECT_NEAR(r.image.at(0, 0, 0), 0.1, 1e-5);
  EXPECT_NEAR(r.image.at(2, 0, 0), 0.3, 1e-5);
  EXPECT_NEAR(mean_rgb(r.image, true), 0.375, 0.375 * 0.02);
}

double rms_error(const sdfrt::FloatImage& a, const sdfrt::FloatImage& ref) {
  double sum = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) sum += std::pow(double(a.at(c, x, y)) - ref.at(c, x, y), 2);
  return std::sqrt(sum / (3.0 * a.width * a.height));
}

// A dim map with a small bright patch (a sun) over a diffuse ball: drawing
// directions by the map's luminance finds the patch at every vertex, so at
// the same samples the error against a long render is far lower than with
// directions drawn uniformly over the sphere.
TEST(PathEnvMap, ImportanceSamplingLowersTheError) {
  test::TempDir dir;
  const std::string exr = (dir.path() / "sun.exr").string();
  test::write_exr_map(exr, 128, 64, [](int x, int y) {
    const bool sun = x < 8 && y >= 18 && y < 24;  // 30 degrees up, behind the camera (the map's centre is +y)
    return sun ? std::array<float, 3>{100, 95, 90} : std::array<float, 3>{0.05f, 0.06f, 0.08f};
  });
  auto scene = [&](const char* sampling, int samples) {
    return fmt::format(
        "camera: {{position: [0, -4, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 30}}\n"
        "render: {{width: 24, height: 24, samples: {}, gamma: 1, exposure: -8, integrator: path, max_bounces: 3}}\n"
        "background: {{map: '{}', sampling: {}, visible: false}}\nlights: []\n"
        "materials:\n  m: {{color: [0.6, 0.6, 0.6]}}\n"
        "scene: {{sphere: {{radius: 1}}, material: m}}\n",
        samples, exr, sampling);
  };
  auto reference = render_text(scene("importance", 1024));
  // exposure -8 (1/256) keeps every sample below the clamp of the tone curve, which would bias the means
  ASSERT_GT(256 * mean_rgb(reference.image, true), 0.3);  // the sun lights the ball
  const double importance = rms_error(render_text(scene("importance", 16)).image, reference.image);
  const double uniform = rms_error(render_text(scene("uniform", 16)).image, reference.image);
  EXPECT_LT(importance, 0.5 * uniform) << "importance " << importance << ", uniform " << uniform;
  // and uniform sampling converges to the same image (both are unbiased)
  const double uniform_long = mean_rgb(render_text(scene("uniform", 1024)).image, true);
  EXPECT_NEAR(uniform_long, mean_rgb(reference.image, true), 0.05 * mean_rgb(reference.image, true));
}

// With up +y the map's centre looks along -z; rotation: A turns it by A degrees
// about up, counter-clockwise seen from above, so the centre moves to
// -z cos A - x sin A. A camera at the origin sees a bright patch at the
// centre where its projection of that direction says.
TEST(PathEnvMap, RotationMovesTheBrightSpot) {
  test::TempDir dir;
  const std::string exr = (dir.path() / "spot.exr").string();
  test::write_exr_map(exr, 256, 128, [](int x, int y) {
    const bool spot = x >= 126 && x < 130 && y >= 62 && y < 66;  // centred on u = v = 0.5
    return spot ? std::array<float, 3>{10, 10, 10} : std::array<float, 3>{0, 0, 0};
  });
  for (double deg : {0.0, 20.0, -35.0}) {
    auto r = render_text(fmt::format(
        "camera: {{position: [0, 0, 0], target: [0, 0, -1], up: [0, 1, 0], fov: 90}}\n"
        "render: {{width: 64, height: 64, samples: 4, gamma: 1, integrator: path}}\n"
        "background: {{map: '{}', rotation: {}}}\nlights: []\n"
        "scene: {{translate: [0, 0, 50], sphere: {{radius: 0.1}}}}\n",
        exr, deg));
    double sx = 0, sy = 0, sw = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const double w = r.image.at(0, x, y);
        sx += w * (x + 0.5), sy += w * (y + 0.5), sw += w;
      }
    ASSERT_GT(sw, 0) << deg;
    const double a = deg * std::numbers::pi / 180;
    const double u = -std::tan(a);  // the centre's screen x at fov 90: x / -z
    EXPECT_NEAR(sx / sw, (u + 1) * 32, 1.0) << deg;
    EXPECT_NEAR(sy / sw, 32, 1.0) << deg;
  }
}

// A map that is missing, not an image, broken, or too large is an error at
// its key, and so are map settings without a map.
TEST(PathEnvMap, BadMapsAreLocated) {
  test::TempDir dir;
  const auto at = [&](const char* name) { return (dir.path() / name).string(); };
  test::write_exr_map(at("wide.exr"), 8193, 2, constant(1));
  test::write_exr_map(at("good.exr"), 8, 4, constant(1));
  {
    std::ofstream(at("junk.hdr")) << "#?RADIANCE\nnot really\n";
    std::ofstream(at("map.png")) << "png";
    std::string good = test::read_text_file(at("good.exr"));
    std::ofstream(at("cut.exr"), std::ios::binary) << good.substr(0, good.size() / 2);
  }
  std::filesystem::create_directory(at("folder.exr"));
  struct Case {
    std::string background, says;
  };
  for (const Case& c : std::vector<Case>{{"{map: '" + at("none.exr") + "'}", "no such file"},
                                         {"{map: '" + at("folder.exr") + "'}", "not a regular file"},
                                         {"{map: '" + at("map.png") + "'}", ".exr or .hdr"},
                                         {"{map: '" + at("junk.hdr") + "'}", "Radiance"},
                                         {"{map: '" + at("cut.exr") + "'}", "OpenEXR"},
                                         {"{map: '" + at("wide.exr") + "'}", "at most"},
                                         {"{map: [1, 2]}", "expected the name"},
                                         {"{rotation: 30}", "there is none"},
                                         {"{map: '" + at("good.exr") + "', intensity: -1}", "intensity"},
                                         {"{map: '" + at("good.exr") + "', sampling: fast}", "sampling"},
                                         {"{map: '" + at("good.exr") + "', sky: {}}", "not both"}}) {
    try {
      test::compile_text("render: {integrator: path}\nbackground: " + c.background + "\nscene: {sphere: {}}\n");
      ADD_FAILURE() << "accepted " << c.background;
    } catch (const SceneError& e) {
      const Diagnostic& d = e.diagnostics().front();
      EXPECT_EQ(d.loc.line, 2) << c.background;
      EXPECT_GE(d.loc.column, 13) << c.background;
      EXPECT_NE(d.message.find(c.says), std::string::npos) << d.message;
    }
  }
}

// Only a path kernel with a map holds the map's code and takes the buffer;
// its file name, here one that would close a comment, never reaches the
// source; a direct kernel is the same with or without a map.
TEST(PathEnvMap, SamplingCodeOnlyWithAMap) {
  test::TempDir dir;
  std::filesystem::create_directory(dir.path() / "odd*");
  const std::string exr = (dir.path() / "odd*" / " #error \" bad.exr").string();  // .../odd*/ #error ...
  test::write_exr_map(exr, 16, 8, constant(0.5f));
  const std::string scene = "scene: {sphere: {radius: 1}}\nlights: []\n";
  auto kernel = [&](const std::string& yaml, int width) {  // the scene first: its lines are the same in each
    return codegen::emit_opencl(test::compile_text(scene + yaml), {width, false}).source;
  };
  const std::string map = "background: {map: '" + exr + "'}\n";
  for (int width : {1, 16}) {
    const std::string plain = kernel("render: {integrator: path}\n", width);
    for (const char* mark : {"envmap", "env_sample", "env_pdf", "env_lookup", "path_glossy_pdf"})
      EXPECT_EQ(plain.find(mark), std::string::npos) << mark;
    const std::string lit = kernel("render: {integrator: path}\n" + map, width);
    for (const char* mark : {"__global const float* envmap)", "env_sample(", "env_pdf(", "env_lookup("})
      EXPECT_NE(lit.find(mark), std::string::npos) << mark;
    EXPECT_EQ(lit.find("bad.exr"), std::string::npos);
    EXPECT_EQ(lit.find("#error"), std::string::npos);
    EXPECT_EQ(kernel("render: {integrator: direct}\n" + map, width), kernel("render: {integrator: direct}\n", width));
  }
  // and it renders
  auto r = render_text(ball("{map: '" + exr + "'}", 16));
  EXPECT_NEAR(mean_rgb(r.image, true), 0.25, 0.03);
}

}  // namespace
}  // namespace sdfc
