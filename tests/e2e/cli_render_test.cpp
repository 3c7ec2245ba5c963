// The sdfc binary as a user runs it: `sdfc render SCENE -o OUT.png --width W
// --height H` in a child process, its exit status, stdout, the PNG it
// leaves (read back with stb_image) and the directory it wrote into.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "e2e_support.hpp"
#include "run_sdfc.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::e2e {
namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string last_line(const std::string& s) {
  std::string t = s;
  while (!t.empty() && (t.back() == '\n' || t.back() == '\r' || t.back() == ' ')) t.pop_back();
  size_t nl = t.find_last_of('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

TEST(CliRender, WritesThePngAndPrintsItsPath) {
  test::device();  // opened first so the child inherits SDFC_KERNEL_CACHE (see sdfc_test_support.hpp)
  test::TempDir out_dir;
  const fs::path scene = fs::path(SDFC_SOURCE_DIR) / "examples" / "mandelbulb.yaml";
  const fs::path png = out_dir.path() / "m.png";
  test::RunResult r =
      test::run_sdfc(fmt::format("render {} -o {} --width 96 --height 54", quote(scene.string()), quote(png.string())));
  ASSERT_EQ(r.code, 0) << "stdout:\n" << r.out << "\nstderr:\n" << r.err;

  // stdout names the image (and only stdout: progress goes to stderr).
  std::string printed = last_line(r.out);
  ASSERT_FALSE(printed.empty()) << "nothing on stdout";
  ASSERT_TRUE(fs::exists(printed)) << "stdout names '" << printed << "', which does not exist";
  EXPECT_TRUE(fs::equivalent(printed, png)) << "stdout names '" << printed << "', not " << png;

  // A valid PNG of the requested size, and nothing else left behind (the
  // writer goes through "<path>.tmp-XXXXXX" and renames).
  int w = 0, h = 0, comp = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(png.c_str(), &w, &h, &comp, 3), stbi_image_free);
  ASSERT_TRUE(pixels) << "stb_image cannot read it: " << stbi_failure_reason();
  EXPECT_EQ(w, 96);
  EXPECT_EQ(h, 54);
  EXPECT_EQ(comp, 3);
  EXPECT_EQ(out_dir.file_names(), std::vector<std::string>{"m.png"});
  for (const auto& name : out_dir.file_names()) EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name;

  // The pixels are the scene's: the same render done in-process (SIMD
  // width 64, the CLI's CPU default; widths agree anyway, see examples_test)
  // quantised to 8 bits matches to one level on >= 99.5% of samples.
  SourceValue doc = load_scene_source(scene.string(), {"render.width=96", "render.height=54"});
  ir::Module m = build_module(doc, scene.string());
  sdfrt::FloatImage img = render(m, 64);
  size_t off = 0, n = size_t(w) * h * 3;
  int distinct[256] = {};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        float v = std::clamp(img.at(c, x, y), 0.0f, 1.0f);
        int want = int(std::lround(v * 255.0f));
        int got = pixels.get()[(size_t(y) * w + x) * 3 + c];
        off += std::abs(got - want) > 1;
        distinct[got] = 1;
      }
  EXPECT_LE(double(off), 0.005 * n) << off << " of " << n << " samples differ from the in-process render";
  int levels = 0;
  for (int v : distinct) levels += v;
  EXPECT_GT(levels, 30) << "the PNG is nearly flat";
}

TEST(CliRender, MissingSceneFailsWithoutWritingAnything) {
  test::TempDir out_dir;
  const fs::path png = out_dir.path() / "m.png";
  test::RunResult r = test::run_sdfc(fmt::format("render {} -o {} --width 96 --height 54",
                                                 quote((out_dir.path() / "no-such-scene.yaml").string()), quote(png.string())));
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.out, "") << "stdout must stay empty on failure";
  EXPECT_NE(r.err.find("no-such-scene.yaml"), std::string::npos) << "the error should name the file:\n" << r.err;
  EXPECT_TRUE(out_dir.file_names().empty());
}

}  // namespace
}  // namespace sdfc::e2e
