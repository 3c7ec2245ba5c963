// Outputs that cannot be written fail with a clear message and a non-zero
// exit, and leave nothing behind: a wrong extension, an unwritable path, a
// full disk, a stopped video.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::RunResult;
using sdfc::test::ScratchDir;
using sdfc::test::dir_entries;

TEST(OutputFailures, AnUnknownExtensionListsTheSupportedOnes) {
  ScratchDir dir;
  RunResult r = sdfc::test::run_sdfc("render examples/primitives.yaml --width 32 --height 16 -o " + dir.file("x.tif"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown file type '.tif'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".png, .exr, .pfm, .jpg (.jpeg), .mp4, .mkv and .webm"), std::string::npos) << r.err;
  EXPECT_TRUE(dir_entries(dir.path()).empty());
  r = sdfc::test::run_sdfc("render examples/primitives.yaml --width 32 --height 16 -q --format png -o " + dir.file("x.tif"));
  EXPECT_EQ(r.code, 0) << "--format names the format: " << r.err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"x.tif"});
}

TEST(OutputFailures, ChoicesAFormatCannotTakeAreUsageErrors) {
  ScratchDir dir;
  const std::string base = "render examples/primitives.yaml -o ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"x.jpg --alpha --width 32 --height 16", "has no alpha channel"},
      {"x.mp4 --bit-depth 16 --width 32 --height 16", "8 bits per channel"},
      {"x.exr --bit-depth 8 --width 32 --height 16", "16 (half, the default) or 32"},
      {"x.png --quality 50 --width 32 --height 16", "no quality setting"},
      {"x.mp4 --quality 60 --width 32 --height 16", "CRF from 0 (best) to 51"},
      {"x.mp4 --aov depth --width 32 --height 16", "holds no AOVs"},
      {"x_%03d.mp4 --frames 0:2 --width 32 --height 16", "drop the frame-number field"},
      {"x.mp4 --width 33 --height 16", "even width and height"},
  };
  for (const auto& [args, message] : cases) {
    RunResult r = sdfc::test::run_sdfc(base + dir.file(args));
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(dir_entries(dir.path()).empty()) << args;
  }
}

TEST(OutputFailures, AnUnwritablePathExitsFourForEveryFormat) {
  ScratchDir dir;
  for (const char* name : {"x.exr", "x.jpg", "x.mp4 --frames 0:1", "x.webm --frames 0:1"}) {
    RunResult r = sdfc::test::run_sdfc("render examples/animated.yaml --width 32 --height 16 -q -o " +
                                       dir.file(std::string("missing/") + name));
    EXPECT_EQ(r.code, 4) << name << ": " << r.err;
    EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << name << ": " << r.err;
    EXPECT_TRUE(dir_entries(dir.path()).empty()) << name;
  }
}

// A really full disk: a 16 KiB tmpfs, as the robustness suite does.
TEST(OutputFailures, AFullDiskLeavesNoFileForExrAndMp4) {
  ScratchDir dir;
  if (geteuid() != 0 || std::system(("mount -t tmpfs -o size=16k tmpfs " + dir.path() + " 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
  for (const char* args : {"--aov depth,normal --bit-depth 32 -o x.exr", "--frames 0:7 --quality 0 -o x.mp4",
                           "--quality 100 -o x.jpg"}) {
    std::string a = args;
    a.replace(a.rfind("x."), 0, dir.path() + "/");
    RunResult r = sdfc::test::run_sdfc("render examples/animated.yaml --width 320 --height 200 -q " + a);
    EXPECT_EQ(r.code, 4) << args << ": " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(dir_entries(dir.path()).empty()) << args << ": no temp file left";
  }
  EXPECT_EQ(std::system(("umount " + dir.path()).c_str()), 0);
}

// Ctrl-C in the middle of a video: nothing, or with --keep-partial a
// playable file of the frames done.
int interrupt_video(const ScratchDir& dir, const std::string& extra, std::string* err) {
  std::vector<std::string> args = {"render", "examples/animated.yaml", "--width", "320", "--height",
                                   "192", "--frames", "0:39", "-o", dir.file("v.mp4")};
  if (!extra.empty()) args.push_back(extra);
  sdfc::test::SdfcProcess sdfc(args, dir.file("stderr"));
  // Readiness wait, not a timing assertion: a few frames are done.
  sdfc.wait_until([&] { return sdfc.stderr_text().find("/40 frames") != std::string::npos; });
  sdfc.signal(SIGINT);
  int code = sdfc.wait();
  *err = sdfc.stderr_text();
  return code;
}

TEST(OutputFailures, CtrlCDuringAVideoLeavesNothingUnlessAskedToKeepIt) {
  ScratchDir dir;
  std::string err;
  EXPECT_EQ(interrupt_video(dir, "", &err), 130) << err;
  EXPECT_NE(err.find("v.mp4 was not written"), std::string::npos) << err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"stderr"}) << "no temp file";
  EXPECT_EQ(interrupt_video(dir, "--keep-partial", &err), 130) << err;
  EXPECT_NE(err.find("partial video"), std::string::npos) << err;
  EXPECT_EQ(dir_entries(dir.path()), (std::vector<std::string>{"stderr", "v.partial.mp4"}));
  EXPECT_GT(std::filesystem::file_size(dir.file("v.partial.mp4")), 1000u);
}

}  // namespace
