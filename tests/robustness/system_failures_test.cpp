// Device and system failures as a user meets them through the sdfc binary:
// no OpenCL platform, an unknown device, a kernel that does not build, an
// unwritable output, a full disk, Ctrl-C during a render.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <sdfrt/image_read.hpp>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

namespace fs = std::filesystem;

void expect_no_exception_text(const RunResult& r) {
  for (const char* bad : {"terminate called", "what():", "internal error", "Sanitizer"})
    EXPECT_EQ(r.err.find(bad), std::string::npos) << r.err;
}

TEST(SystemFailures, NoOpenCLPlatformExitsThreeWithAHint) {
  ScratchDir vendors;  // an ICD directory with no drivers in it
  ScratchDir out;
  std::string env = "OCL_ICD_VENDORS=" + vendors.path() + " ";
  RunResult r = run_sdfc("render examples/mandelbulb.yaml --width 32 --height 18 -q -o " + out.file("m.png"), env);
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("no OpenCL platform"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("pocl-opencl-icd"), std::string::npos) << "should say what to install: " << r.err;
  EXPECT_EQ(r.err.find("CL_"), std::string::npos) << "no OpenCL error code: " << r.err;
  EXPECT_TRUE(dir_entries(out.path()).empty());
  expect_no_exception_text(r);

  RunResult d = run_sdfc("devices", env);
  EXPECT_EQ(d.code, 3) << d.err;
  EXPECT_NE(d.err.find("no OpenCL device found"), std::string::npos) << d.err;
  EXPECT_NE(d.err.find("pocl-opencl-icd"), std::string::npos) << d.err;
}

TEST(SystemFailures, UnknownDeviceNameExitsThreeListingTheDevices) {
  RunResult r = run_sdfc("render examples/mandelbulb.yaml -q -o /tmp/never.png --device no-such-gpu");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("no-such-gpu"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0:0"), std::string::npos) << "should list the ids that exist: " << r.err;
  expect_no_exception_text(r);
}

// Ids that do not exist, in every form and from every place a device is named.
TEST(SystemFailures, DeviceIdsThatDoNotExistExitThree) {
  ScratchDir dir;
  const std::string render = "render examples/primitives.yaml --width 32 --height 18 -q -o " + dir.file("p.png");
  struct Case {
    std::string args, env, id, source;
  } cases[] = {{render + " --device 7:0", "", "'7:0'", "from the device argument"},
               {render + " --device 0:9", "", "'0:9'", "from the device argument"},
               {render + " --device 42", "", "'42'", "from the device argument"},
               {render, "SDFC_DEVICE=5:5 ", "'5:5'", "from SDFC_DEVICE"},
               {"view examples/primitives.yaml --benchmark 1 --device 3:1", "SDL_VIDEODRIVER=dummy ", "'3:1'",
                "from the device argument"}};
  for (const Case& c : cases) {
    RunResult r = run_sdfc(c.args, c.env);
    EXPECT_EQ(r.code, 3) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find("unknown OpenCL device " + c.id + " (" + c.source), std::string::npos)
        << c.env << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find("Available devices:\n  0:0"), std::string::npos) << r.err;
    expect_no_exception_text(r);
  }
  EXPECT_TRUE(dir_entries(dir.path()).empty());
}

TEST(SystemFailures, KernelBuildFailureShowsTheLogAndTheKernelLines) {
  ScratchDir dir;
  RunResult c = run_sdfc("compile examples/primitives.yaml -o " + dir.file("k.cl"));
  ASSERT_EQ(c.code, 0) << c.err;
  // Break one line the way a hand edit might: an undeclared name.
  std::string src = read_text(dir.file("k.cl"));
  size_t at = src.find("real scene_dist(");
  ASSERT_NE(at, std::string::npos);
  size_t body = src.find('{', at);
  src.insert(body + 1, "\n  real broken_here = undeclared_thing * 2.0f;");
  dir.write("broken.cl", src);
  RunResult r = run_sdfc("render examples/primitives.yaml --width 32 --height 18 -q --kernel " + dir.file("broken.cl") +
                         " -o " + dir.file("p.png"));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_NE(r.err.find("undeclared_thing"), std::string::npos) << "the log and the kernel line: " << r.err;
  EXPECT_NE(r.err.find("generated kernel source at the errors"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("p.png")));
  expect_no_exception_text(r);
}

TEST(SystemFailures, UnreadableKernelFileIsAUsageError) {
  RunResult r = run_sdfc("render examples/primitives.yaml -q --kernel /nonexistent/k.cl -o /tmp/never.png");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot read /nonexistent/k.cl"), std::string::npos) << r.err;
}

TEST(SystemFailures, OutputIntoAFileAsDirectoryExitsFour) {
  ScratchDir dir;
  dir.write("plain", "x");
  RunResult r = run_sdfc("render examples/primitives.yaml --width 32 --height 18 -q -o " + dir.file("plain/p.png"));
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find(dir.file("plain/p.png")), std::string::npos) << "names the path: " << r.err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"plain"});
  expect_no_exception_text(r);
}

// `ulimit -f` makes writes past the limit fail with EFBIG, like a full disk.
TEST(SystemFailures, FileSizeLimitExitsFourLeavingNoFileAndTheOldOneIntact) {
  ScratchDir dir;
  dir.write("k.cl", "the previous kernel");
  RunResult r = run_sdfc("compile examples/primitives.yaml -o " + dir.file("k.cl"), "ulimit -f 4; ");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("too large"), std::string::npos) << "strerror(EFBIG): " << r.err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"k.cl"}) << "no temp file left";
  EXPECT_EQ(read_text(dir.file("k.cl")), "the previous kernel");
  expect_no_exception_text(r);
}

// A really full disk: a 16 KiB tmpfs (needs root and a kernel that lets us mount).
TEST(SystemFailures, FullDiskExitsFourLeavingNoFileAndTheOldImageIntact) {
  ScratchDir dir;
  if (geteuid() != 0 || std::system(("mount -t tmpfs -o size=16k tmpfs " + dir.path() + " 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
  dir.write("p.png", "the previous image");
  RunResult r = run_sdfc("render examples/primitives.yaml --width 320 --height 200 -q -o " + dir.file("p.png"));
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir.file("p.png")), std::string::npos) << "names the path: " << r.err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"p.png"}) << "no temp file left";
  EXPECT_EQ(read_text(dir.file("p.png")), "the previous image");
  expect_no_exception_text(r);
  EXPECT_EQ(std::system(("umount " + dir.path()).c_str()), 0);
}

// PoCL cannot write its kernel cache: with a cold cache the build fails
// without a compiler diagnostic (exit 3); with the program cached but not
// its work-group function, PoCL aborts at launch. Either way the user is
// told what probably happened, and nothing is written.
TEST(SystemFailures, FullDiskDuringTheDriversKernelBuildIsExplained) {
  ScratchDir dir, pocl_cache;
  RunResult r = run_sdfc("render examples/primitives.yaml --width 64 --height 40 -q -o " + dir.file("p.png"),
                         "export POCL_CACHE_DIR=" + pocl_cache.path() + " SDFC_KERNEL_CACHE=0; ulimit -f 4; ");
  if (r.code == 3) {
    EXPECT_NE(r.err.find("the driver itself failed"), std::string::npos) << r.err;
  } else {
    EXPECT_EQ(r.code, 128 + SIGABRT) << r.err;
    EXPECT_NE(r.err.find("the OpenCL driver aborted"), std::string::npos) << r.err;
  }
  EXPECT_NE(r.err.find("full disk or"), std::string::npos) << r.err;
  EXPECT_TRUE(dir_entries(dir.path()).empty());
}

struct Interrupted {
  int code;
  std::string err;
  double ms_to_exit = 0;  // from the signal to the process's end
};

// The tiles done in the last progress line ("717/1024 tiles ..."), or -1.
int tiles_done(const std::string& err) {
  size_t at = err.rfind(" tiles ");
  if (at == std::string::npos) return -1;
  size_t slash = err.rfind('/', at), start = err.find_last_not_of("0123456789", slash - 1);
  return std::atoi(err.substr(start + 1, slash - start - 1).c_str());
}

// Starts a long render of the Mandelbulb (SIDE x SIDE in 32-pixel tiles),
// waits until its progress shows more than `min_tiles` tiles done, sends
// SIGINT (what Ctrl-C does) and returns how it ended.
Interrupted render_and_interrupt(const ScratchDir& dir, const std::vector<std::string>& extra, int side = 2048,
                                 int min_tiles = 0, int signal = SIGINT, int tile = 32) {
  std::vector<std::string> args = {"render", "examples/mandelbulb.yaml", "--width", std::to_string(side),
                                   "--height", std::to_string(side), "--tile", std::to_string(tile), "-o", dir.file("big.png")};
  args.insert(args.end(), extra.begin(), extra.end());
  SdfcProcess sdfc(args, dir.file("stderr"));
  // Readiness wait, not a timing assertion: the progress lines appear once
  // the kernel is built and tiles are done.
  // min_tiles < 0: wait for the kernel build, then a second into the first tile.
  const bool ready = sdfc.wait_until([&] {
    std::string err = sdfc.stderr_text();
    return min_tiles < 0 ? err.find("kernel built") != std::string::npos : tiles_done(err) > min_tiles;
  });
  if (ready && min_tiles < 0) std::this_thread::sleep_for(std::chrono::seconds(1));
  auto signalled = std::chrono::steady_clock::now();
  sdfc.signal(signal);  // nothing when it ended early: its exit code says how
  int code = sdfc.wait();
  double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - signalled).count();
  return {code, sdfc.stderr_text(), ms};
}

// Rows of an image that are all black, and rows with some light.
std::pair<int, int> black_and_lit_rows(const sdfrt::FloatImage& img) {
  int black = 0, lit = 0;
  for (int y = 0; y < img.height; ++y) {
    bool any = false;
    for (int c = 0; c < 3 && !any; ++c) {
      auto p = img.plane(c);
      for (int x = 0; x < img.width && !any; ++x) any = p[std::size_t(y) * img.width + x] > 0.0f;
    }
    (any ? lit : black) += 1;
  }
  return {black, lit};
}

TEST(SystemFailures, CtrlCLeavesTheFinalNameUntouched) {
  ScratchDir dir;
  dir.write("big.png", "the previous image");
  Interrupted r = render_and_interrupt(dir, {});
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("sdfc: cancelled"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("big.png was not written"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--keep-partial"), std::string::npos) << "says how to keep the tiles: " << r.err;
  EXPECT_EQ(dir_entries(dir.path()), (std::vector<std::string>{"big.png", "stderr"})) << "no temp or partial file";
  EXPECT_EQ(read_text(dir.file("big.png")), "the previous image");
}

// One 2048x2048 tile of the Mandelbulb at 100000 steps takes minutes; the
// renderer launches it in slices of about 100 ms, so Ctrl-C still stops it
// at once. The bound is loose (a loaded machine); before the slices the
// process went on until the tile was done.
TEST(SystemFailures, CtrlCStopsWithinAOneTileRenderAtOnce) {
  ScratchDir dir;
  Interrupted r = render_and_interrupt(dir, {"--set", "render.max_steps=100000", "--set", "render.hit_epsilon=0.01"},
                                       2048, -1, SIGINT, 2048);
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_LT(r.ms_to_exit, 5000) << "Ctrl-C took " << r.ms_to_exit << " ms";
}

// The output's temp file has no name until it is complete (O_TMPFILE), so
// even a SIGKILL mid-render leaves nothing beside the output.
TEST(SystemFailures, SigkillLeavesNoTempFile) {
  ScratchDir dir;
  Interrupted r = render_and_interrupt(dir, {}, 2048, 8, SIGKILL);
  EXPECT_EQ(r.code, 128 + SIGKILL) << r.err;
  EXPECT_EQ(dir_entries(dir.path()), (std::vector<std::string>{"stderr"})) << "no temp file left";
}

TEST(SystemFailures, CtrlCWithKeepPartialWritesTheTilesDoneToAPartialFile) {
  ScratchDir dir;
  Interrupted r = render_and_interrupt(dir, {"--keep-partial"});
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("partial image: " + dir.file("big.partial.png")), std::string::npos) << r.err;
  EXPECT_EQ(dir_entries(dir.path()), (std::vector<std::string>{"big.partial.png", "stderr"})) << "never big.png";
  // A whole image of the full size: rendered rows at the top, black below.
  sdfrt::FloatImage img = sdfrt::read_png(dir.file("big.partial.png"));
  EXPECT_EQ(img.width, 2048);
  EXPECT_EQ(img.height, 2048);
  auto [black, lit] = black_and_lit_rows(img);
  EXPECT_GT(lit, 0) << "holds the tiles done";
  EXPECT_GT(black, 0) << "the tiles not done are black";
}

// 512x512 in 32-pixel tiles is 256 tiles a pass: stopped after 300 tiles,
// the first pass is complete and the partial image has no black row.
TEST(SystemFailures, CtrlCWithKeepPartialDuringSamplePassesKeepsTheMeanSoFar) {
  ScratchDir dir;
  Interrupted r = render_and_interrupt(dir, {"--keep-partial", "--set", "render.samples=64"}, 512, 300);
  EXPECT_EQ(r.code, 130) << r.err;
  EXPECT_NE(r.err.find("partial image: " + dir.file("big.partial.png")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stopped in pass"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("stopped in pass 1 "), std::string::npos) << r.err;
  EXPECT_EQ(dir_entries(dir.path()), (std::vector<std::string>{"big.partial.png", "stderr"})) << "never big.png";
  sdfrt::FloatImage img = sdfrt::read_png(dir.file("big.partial.png"));
  EXPECT_EQ(img.width, 512);
  EXPECT_EQ(img.height, 512);
  EXPECT_EQ(black_and_lit_rows(img).first, 0);
}

TEST(SystemFailures, AFinishedRenderWithKeepPartialLeavesNoPartialFile) {
  ScratchDir dir;
  dir.write("p.partial.png", "left by an earlier interrupted run");
  RunResult r = run_sdfc("render examples/primitives.yaml --width 64 --height 40 -q --keep-partial -o " +
                         dir.file("p.png"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dir_entries(dir.path()), std::vector<std::string>{"p.png"});
}

}  // namespace
}  // namespace sdfc::test
