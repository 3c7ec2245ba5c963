// What `check` accepts builds and renders right; what cannot render right
// is refused with a message (hostile-input classes 6, 7 and 9).
#include <gtest/gtest.h>

#include <sdfrt/image_read.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

const std::string kView = "camera: {position: [0, -4, 1], target: [0, 0, 0]}\nrender: {width: 16, height: 16}\n";

RunResult render_text(const ScratchDir& dir, const std::string& yaml, const std::string& extra = "",
                      const std::string& out = "o.png") {
  return run_sdfc("render " + dir.write("s.yaml", yaml) + " -q -o " + dir.file(out) + " " + extra);
}

RunResult check_text(const ScratchDir& dir, const std::string& yaml) {
  return run_sdfc("check " + dir.write("c.yaml", yaml));
}

TEST(AcceptedBuilds, AOneStepHybridBuilds) {
  ScratchDir dir;
  RunResult r = render_text(dir, kView + "scene: {hybrid: {steps: [{mandelbulb: {power: 8}}], iterations: 6}}\n");
  EXPECT_EQ(r.code, 0) << r.err.substr(0, 1500);
}

TEST(AcceptedBuilds, ScalesAndGammaWhoseInverseIsNoFloatAreRefused) {
  ScratchDir dir;
  for (const char* bad : {"scene: {sphere: {radius: 1}, scale: 1e-300}\n",
                                 "scene: {sphere: {radius: 1}, scale: [1e-39, 1, 1]}\n",
                                 "render: {gamma: 1e-300}\nscene: {sphere: {radius: 1}}\n"}) {
    SCOPED_TRACE(bad);
    RunResult r = check_text(dir, bad);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.err.find("is too small; the smallest value that renders is"), std::string::npos) << r.err;
  }
  // Allowed scales that fold into one past the float range still build.
  std::string s = "{sphere: {radius: 1}}";
  for (int i = 0; i < 11; ++i) s = "{union: [" + s + "], scale: 0.0001}";
  RunResult r = render_text(dir, kView + "scene: {union: [" + s + "], scale: 1}\n");
  EXPECT_EQ(r.code, 0) << r.err.substr(0, 1500);
}

TEST(AcceptedBuilds, ADisplaceOf300TermsIsRefusedNotABuildFailure) {
  ScratchDir dir;
  std::string sum = "0.0001*sin(x)";
  for (int i = 1; i < 300; ++i) sum += "+0.0001*sin(x)";
  RunResult r = render_text(dir, kView + "scene: {sphere: {radius: 1}, displace: {expr: \"" + sum + "\"}}\n");
  EXPECT_EQ(r.code, 1) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find("operations deep"), std::string::npos) << r.err.substr(0, 500);
}

TEST(AcceptedBuilds, BadNumbersOnTheCommandLineAreUsageErrors) {
  ScratchDir dir;
  std::string scene = kView + "scene: {sphere: {radius: 1}}\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--fps nan --frames 0:2", "f_%02d.png"}, {"--reference --reference-epsilon nan", "o.png"},
      {"--frames 99999999999999999999", "o.png"}, {"--frames 31000000 --fps 30", "o.png"},
      {"--frames 0:1", "fr_%999999999d.png"}};
  for (const auto& [args, out] : cases) {
    SCOPED_TRACE(args);
    RunResult r = render_text(dir, scene, args, out);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 600u);
  }
}

// CLI::Range lets NaN through: every floating-point option of every command
// refuses it (mesh --fps nan meshed at time NaN; render's was fixed alone).
TEST(AcceptedBuilds, NanIsRefusedByEveryNumberOption) {
  ScratchDir dir;
  const std::string scene = dir.write("s.yaml", kView + "scene: {sphere: {radius: 1}}\n");
  for (const std::string& args :
       {"mesh " + scene + " --frames 0:1 --fps nan -o " + dir.file("m_%d.stl"), "mesh " + scene + " --iso nan -o " + dir.file("m.stl"),
        "mesh " + scene + " --voxel nan -o " + dir.file("m.stl"), "mesh " + scene + " --adaptivity nan -o " + dir.file("m.stl"),
        "mesh " + scene + " --memory-limit nan -o " + dir.file("m.stl"),
        "farm slurm " + scene + " --frames 0:1 --fps nan -o " + dir.file("f_%d.png"),
        "compare " + scene + " " + scene + " --pixel-threshold nan", "view " + scene + " --benchmark nan",
        "view " + scene + " --orbit-degrees nan"}) {
    SCOPED_TRACE(args);
    RunResult r = run_sdfc(args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("finite"), std::string::npos) << r.err;
  }
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"s.yaml"}) << "nothing was written";
}

TEST(AcceptedBuilds, MaxDistanceHoldsOnTheFirstStep) {
  ScratchDir dir;
  auto image = [&](const std::string& extra_render, const std::string& where) {
    RunResult r = render_text(dir, "camera: {position: [0, -3, 0], target: [0, 0, 0]}\nrender: {width: 16, height: 16" +
                                       extra_render + "}\nscene: {box: {size: [1, 1, 1]}, translate: " + where + "}\n");
    EXPECT_EQ(r.code, 0) << r.err;
    return read_text(dir.file("o.png"));
  };
  std::string seen = image("", "[0, 0, 0]");                         // 2.5 away: drawn
  std::string cut = image(", max_distance: 1", "[0, 0, 0]");         // beyond max_distance
  std::string empty = image(", max_distance: 1", "[0, 100, 0]");     // nothing in view
  EXPECT_NE(cut, seen);
  EXPECT_EQ(cut, empty) << "the box past max_distance was drawn";
}

TEST(AcceptedBuilds, ValuesThatRenderNothingAreRefused) {
  ScratchDir dir;
  for (const char* bad : {"render: {normal_step: 1e-300}\nscene: {sphere: {radius: 1}}\n",
                                 "camera: {fov: 1e-300}\nscene: {sphere: {radius: 1}}\n",
                                 "scene: {sphere: {radius: 1}, displace: {expr: \"0.01*sin(exp(100*x))\"}}\n"}) {
    SCOPED_TRACE(bad);
    RunResult r = check_text(dir, bad);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.err.find("c.yaml:"), std::string::npos) << r.err;
  }
}

TEST(AcceptedBuilds, ScenesTheDocsCallValidAreAccepted) {
  ScratchDir dir;
  for (const char* good : {
           "scene: {sphere: {radius: 1}, displace: {expr: \"0.1*sin(x)*sin(x)\"}}\n",
           "scene: {link: {length: 0.5, major_radius: 0.4, minor_radius: 0.1}, displace: {expr: \"0.074*sin(2.745*z)\"}}\n",
           "scene: {quad: {a: [-0.5, -0.5, 0], b: [0.5, -0.5, 0.0001], c: [0.5, 0.5, 0], d: [-0.5, 0.5, 0.0001], "
           "thickness: 0.05}}\n"}) {
    SCOPED_TRACE(good);
    RunResult r = check_text(dir, good);
    EXPECT_EQ(r.code, 0) << r.err;
  }
}

// The largest difference of any channel of two PNGs of the same size.
float max_difference(const std::string& a, const std::string& b) {
  sdfrt::FloatImage x = sdfrt::read_png(a), y = sdfrt::read_png(b);
  if (x.width != y.width || x.height != y.height || x.data.size() != y.data.size()) return 1e9f;
  float d = 0;
  for (size_t i = 0; i < x.data.size(); ++i) d = std::max(d, std::fabs(x.data[i] - y.data[i]));
  return d;
}

// The docs allow an animated radius on every smooth blend; with kind: cubic
// or exponential it was refused ("cannot be animated"). Frames 0 and 1 at
// 2 fps are times 0 and 0.5, where the radius is 0.1 and 0.5 (exact in
// float); each frame must look like the scene with that radius written as a
// number. The animated scene's bounds are those of its largest radius, so
// its rays start elsewhere: a fine hit epsilon makes both converge on the
// same surface (at the default 0.5 px they differ by up to 13 levels).
TEST(AcceptedBuilds, AnAnimatedRadiusOnACubicOrExponentialBlendRenders) {
  ScratchDir dir;
  auto scene = [](const std::string& kind, const std::string& radius) {
    return "camera: {position: [0, -4, 1], target: [0, 0, 0]}\n"
           "render: {width: 32, height: 32, hit_epsilon: 0.05, max_steps: 1000}\nscene:\n  smooth_union:\n    kind: " + kind + "\n    radius: " + radius +
           "\n    children:\n      - {sphere: {radius: 0.6}, translate: [0.45, 0, 0]}\n"
           "      - {sphere: {radius: 0.6}, translate: [-0.45, 0, 0.2]}\n";
  };
  for (const std::string kind : {"cubic", "exponential"}) {
    SCOPED_TRACE(kind);
    RunResult r = render_text(dir, scene(kind, "\"clamp(0.1 + 0.8*time, 0.1, 0.5)\""), "--fps 2 --frames 0:1", "a_%d.png");
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_EQ(render_text(dir, scene(kind, "0.1"), "", "s_0.png").code, 0);
    ASSERT_EQ(render_text(dir, scene(kind, "0.5"), "", "s_1.png").code, 0);
    EXPECT_GT(max_difference(dir.file("a_0.png"), dir.file("a_1.png")), 0.1f) << "the radius did not change the image";
    EXPECT_LE(max_difference(dir.file("a_0.png"), dir.file("s_0.png")), 2.5f / 255) << "time 0 is not radius 0.1";
    EXPECT_LE(max_difference(dir.file("a_1.png"), dir.file("s_1.png")), 2.5f / 255) << "time 0.5 is not radius 0.5";
  }
}

// A camera inside a solid sees no shape, and its normals are computed with
// a step near float resolution (10 degrees off): check and render say so,
// with the camera's position and line, and still render.
TEST(AcceptedBuilds, ACameraInsideASolidIsWarnedAbout) {
  ScratchDir dir;
  const std::string inside = "render: {width: 16, height: 16}\ncamera: {position: [0.5, -0.25, 0], target: [0, 0, 0]}\n"
                             "scene: {box: {size: [2, 2, 2]}}\n";
  const std::string warning = "s.yaml:2:9: warning: the camera at [0.5, -0.25, 0] is inside a solid";
  RunResult r = render_text(dir, inside);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  r = run_sdfc("check " + dir.file("s.yaml"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find(warning), std::string::npos) << r.err;
  // A path key inside, at the time when an animated sphere has grown around it.
  r = render_text(dir, "render: {width: 16, height: 16}\ncamera:\n  path:\n    keys:\n"
                       "      - {time: 0, position: [0, -3, 0], target: [0, 0, 0]}\n"
                       "      - {time: 2, position: [0, -1.5, 0], target: [0, 0, 0]}\n"
                       "scene: {sphere: {radius: \"clamp(time, 0.5, 2)\"}}\n");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("s.yaml:3:3: warning: the camera at [0, -1.5, 0] (path key at time 2) is inside"), std::string::npos)
      << r.err;
  r = render_text(dir, kView + "scene: {box: {size: [2, 2, 2]}}\n");  // outside: nothing to say
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(AcceptedBuilds, YamlTheFormatDoesNotHaveIsRefused) {
  ScratchDir dir;
  RunResult r = check_text(dir, "scene: {sphere: {radius: 1}}\n---\nscene: {box: {}}\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("c.yaml:2:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("second YAML document"), std::string::npos) << r.err;
  r = check_text(dir, "scene: {sphere: {radius: !foo 1}}\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown tag '!foo'"), std::string::npos) << r.err;
}

TEST(AcceptedBuilds, SmallerMistakesGetMessagesThatSayWhatIsWrong) {
  ScratchDir dir;
  RunResult r = check_text(dir, "scene: {sphere: {radius: 1e-320}}\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("too close to zero"), std::string::npos) << r.err;
  r = check_text(dir, "scene: {sphere: {radius: \"1e6+1\"}}\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("too large (the limit is 1e+06)"), std::string::npos) << r.err;
  std::string list = "[0";
  for (int i = 0; i < 300000; ++i) list += ",0";
  r = check_text(dir, "scene: {sphere: {radius: 1}}\nextra: " + list + "]\n");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("more than 200000 values"), std::string::npos) << r.err.substr(0, 300);
  EXPECT_EQ(r.err.find("alias"), std::string::npos) << "no alias in this scene: " << r.err.substr(0, 300);
  std::string scene = dir.write("k.yaml", kView + "scene: {sphere: {radius: 1}}\n");
  r = run_sdfc("render " + scene + " -q -o " + dir.file("o.png") + " --kernel " + dir.path());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("is not a file"), std::string::npos) << r.err;
  r = run_sdfc("render " + scene + " -q -o " + dir.file("o.png") + " --kernel " + dir.write("e.cl", ""));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("is empty"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sdfc::test
