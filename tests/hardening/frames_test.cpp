// Frame sequences from the command line: "%%" in a name pattern is one '%',
// and a --frames range is iterated, never listed, so its memory does not
// grow with its length (hostile-input classes 5 and 9).
#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

const char* kScene = "camera: {position: [0, -4, 1], target: [0, 0, 0]}\nrender: {width: 8, height: 8}\n"
                     "scene: {sphere: {radius: 1}}\n";

// As in caps_test.cpp: ASan reserves terabytes of shadow address space,
// which an address-space limit forbids, so the sanitizer build runs without.
#if defined(__SANITIZE_ADDRESS__)
constexpr long kAddressSpaceKib = 0;
#else
constexpr long kAddressSpaceKib = 4000000;
#endif

TEST(Frames, DoublePercentInAPatternIsOnePercent) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", kScene);
  RunResult r = run_sdfc("render " + scene + " -q --frames 0:1 -o '" + dir.file("p_100%%_%02d.png") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("p_100%_00.png") + "\n" + dir.file("p_100%_01.png") + "\n");
  // "%%d" is the text "%d", not a second field.
  r = run_sdfc("render " + scene + " -q --frames 3:4 -o '" + dir.file("q_%%d_%d.png") + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("q_%d_3.png") + "\n" + dir.file("q_%d_4.png") + "\n");
  EXPECT_EQ(dir_entries(dir.path()),
            (std::vector<std::string>{"p_100%_00.png", "p_100%_01.png", "q_%d_3.png", "q_%d_4.png", "s.yaml"}));
  // Two real fields are still one too many.
  r = run_sdfc("render " + scene + " -q --frames 0:1 -o '" + dir.file("r_%d_%d.png") + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("need one frame-number field"), std::string::npos) << r.err;
}

// --frames 0:2147483647 as a list of ints is 8 GiB: under a 4 GB address
// space it could not start. As a range, frames render at once, for a shard
// of it too; the test stops the run (Ctrl-C) after the first frames.
TEST(Frames, TheLongestRangeRendersItsFirstFramesWithinBoundedMemory) {
  struct Case {
    std::vector<std::string> extra;
    std::string first_file;  // the task's first frame, numbered from FIRST
  };
  const std::vector<Case> cases = {
      {{}, "f_0.png"},
      {{"--shard", "1/2"}, "f_1073741824.png"},                       // the second half
      {{"--shard", "2/3", "--shard-mode", "strided"}, "f_2.png"}};   // every third from 2
  for (const Case& c : cases) {
    ScratchDir dir;
    std::vector<std::string> args = {"render", dir.write("s.yaml", kScene), "--frames", "0:2147483647", "--fps",
                                     "10000", "-o", dir.file("f_%d.png")};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    SdfcProcess sdfc(args, dir.file("stderr"), kAddressSpaceKib);
    // Readiness wait, not a timing assertion: the task's first frame is written.
    const bool started = sdfc.wait_until([&] { return std::filesystem::exists(dir.file(c.first_file)); });
    sdfc.signal(SIGINT);
    const int code = sdfc.wait();
    EXPECT_TRUE(started) << c.first_file << " never appeared: " << sdfc.stderr_text().substr(0, 800);
    EXPECT_EQ(code, 130) << sdfc.stderr_text().substr(0, 800);
  }
}

}  // namespace
}  // namespace sdfc::test
