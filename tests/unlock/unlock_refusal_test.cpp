// What cannot be unlocked is refused with the value's location and why, and
// `sdfc compile --unlock` shows where each unlocked value sits.
#include <gtest/gtest.h>

#include "run_sdfc.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "unlock_support.hpp"

namespace sdfc::test {
namespace {

const char* kMandelbox =
    "scene:\n"
    "  mandelbox: {scale: 2, iterations: 10}\n"
    "  translate: [0, 0, 0.5]\n";

std::string error_of(const std::string& yaml, const std::string& unlock) {
  try {
    compile_unlocked(yaml, {unlock});
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(UnlockRefusal, ValuesThatShapeTheCodeAreRefused) {
  std::string it = error_of(kMandelbox, "scene.mandelbox.iterations");
  EXPECT_NE(it.find("unlock.yaml:2:"), std::string::npos) << it;
  EXPECT_NE(it.find("cannot be unlocked"), std::string::npos) << it;
  EXPECT_NE(it.find("rebuild"), std::string::npos) << it;
  // The scale may be animated, so it unlocks, but only over a range its own check accepts.
  EXPECT_NE(error_of(kMandelbox, "scene.mandelbox.scale=0.5:2.5").find("|scale| > 1"), std::string::npos);
  EXPECT_EQ(error_of(kMandelbox, "scene.mandelbox.scale"), "");  // its documented range keeps clear of it
  EXPECT_EQ(error_of(kMandelbox, "scene.mandelbox.scale=1.5:2.5"), "");
  EXPECT_EQ(error_of(kMandelbox, "scene.translate[2]"), "");  // a transform may be animated, so it unlocks
}

TEST(UnlockRefusal, BadPathsAndRangesAreErrors) {
  EXPECT_NE(error_of(kMandelbox, "scene.mandelbulb.power").find("no value at this path"), std::string::npos);
  EXPECT_NE(error_of(kMandelbox, "scene.translate").find("unlock the list's items one by one"), std::string::npos);
  EXPECT_NE(error_of(kMandelbox, "scene.translate[2]=1:0").find("LO <= HI"), std::string::npos);
  std::string outside = error_of("scene: {sphere: {radius: 1}}\n", "scene.sphere.radius=-1:2");
  EXPECT_NE(outside.find("must stay within its allowed values"), std::string::npos) << outside;
}

TEST(UnlockRefusal, CompileShowsTheSlots) {
  ScratchDir dir;
  std::string path = dir.write("s.yaml", "scene: {sphere: {radius: 1.5}}\n");
  RunResult r = run_sdfc("compile " + path + " --unlock scene.sphere.radius");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("((scalar)unlocked[0])"), std::string::npos);
  EXPECT_NE(r.err.find("unlocked[0] = scene.sphere.radius (1.5), range 0.1875 to 3"), std::string::npos) << r.err;
  RunResult bad = run_sdfc("compile " + path + " --unlock scene.sphere.radus");
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("no value at this path"), std::string::npos) << bad.err;
  EXPECT_NE(run_sdfc("compile --help").out.find("--unlock"), std::string::npos);
}

}  // namespace
}  // namespace sdfc::test
