// Caps that keep a hostile scene from crashing, hanging or filling memory:
// expression size (no recursion proportional to the input), the cost per
// sample, lights in the kernel size, input file size and kind, echoed text.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_sdfc.hpp"
#include "sdfc/expr/expr.hpp"
#include "sdfc/support/diagnostics.hpp"

namespace sdfc::test {
namespace {

// "0.5+0*(1+1+...+1)" with `terms` ones: a flat chain, one tree level per term.
std::string flat_chain(size_t terms) {
  std::string s = "0.5+0*(1";
  for (size_t i = 1; i < terms; ++i) s += "+1";
  return s + ")";
}

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

// A memory limit makes a refusal that reads the whole file fail loudly. ASan
// reserves terabytes of shadow address space, which `ulimit -v` forbids, so
// the sanitizer build checks the same refusals without the limit.
#if defined(__SANITIZE_ADDRESS__)
constexpr const char* kMemoryLimit = "";
#else
constexpr const char* kMemoryLimit = "ulimit -v 4000000; ";
#endif

// The height cap is 120; 10x it and the 100 000 terms are refused
// with a message, and never reach a recursive pass.
TEST(Caps, LongFlatExpressionChainsAreRefusedNotCrashed) {
  auto file = std::make_shared<const std::string>("t.yaml");
  for (size_t terms : {1200u, 100000u}) {
    SCOPED_TRACE(terms);
    std::string text = flat_chain(terms);
    try {
      expr::parse(text, SourceLoc(file, 1, 1), {"x"});
      ADD_FAILURE() << "accepted";
    } catch (const SceneError& e) {
      std::string msg = e.what();
      EXPECT_TRUE(msg.find("operations deep") != std::string::npos || msg.find("characters long") != std::string::npos)
          << first_line(msg);
      EXPECT_LT(msg.size(), 400u) << "the expression is not echoed whole";
    }
  }
  // Under the cap: parsed, folded, printed.
  auto e = expr::fold(expr::parse(flat_chain(100), SourceLoc(file, 1, 1), {"x"}));
  EXPECT_EQ(expr::to_string(e), "0.5");
}

TEST(Caps, A200KbDisplaceSumIsASceneErrorThroughTheBinary) {
  ScratchDir dir;
  std::string sum = "0.001*sin(x)";
  while (sum.size() < 200000) sum += "+0.001*sin(x)";
  std::string scene = dir.write("d.yaml", "scene: {sphere: {radius: 1}, displace: {expr: \"" + sum + "\"}}\n");
  RunResult r = run_sdfc("check " + scene);
  EXPECT_EQ(r.code, 1) << first_line(r.err);
  EXPECT_NE(r.err.find("d.yaml:1:"), std::string::npos) << first_line(r.err);
  EXPECT_LT(r.err.size(), 2000u);
}

// The longest chain allowed builds: the emitted OpenCL stays within clang's
// 256 nested brackets.
TEST(Caps, TheLongestAllowedDisplaceBuildsAndRenders) {
  ScratchDir dir;
  std::string sum = "0.0005*sin(3*x)";
  for (int i = 1; i < 110; ++i) sum += "+0.0005*sin(3*x)";
  std::string scene = dir.write("d.yaml", "render: {width: 16, height: 16}\nscene: {sphere: {radius: 1}, displace: {expr: \"" +
                                              sum + "\"}}\n");
  RunResult r = run_sdfc("render " + scene + " -q -o " + dir.file("o.png"));
  EXPECT_EQ(r.code, 0) << r.err.substr(0, 2000);
}

TEST(Caps, NestedPolarRepeatsOverTheCostCapAreRefusedUnlessAllowed) {
  ScratchDir dir;
  std::string s = "{sphere: {radius: 0.1}, translate: [1, 0, 0]}";
  for (int i = 0; i < 40; ++i) s = "{union: [" + s + "], polar_repeat: {count: 2}}";
  std::string scene = dir.write("p.yaml", "render: {width: 8, height: 8}\nscene: " + s + "\n");
  RunResult r = run_sdfc("check " + scene);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("estimated cost is"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("over the limit of 1e+08"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-slow"), std::string::npos) << r.err;
  r = run_sdfc("check --allow-slow " + scene);
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST(Caps, LightsCountInTheKernelSize) {
  ScratchDir dir;
  std::string lights = "lights:\n";
  for (int i = 0; i < 300; ++i)
    lights += "  - point: {position: [" + std::to_string(i % 17) + ", -3, 2], intensity: 0.01, shadows: soft}\n";
  std::string scene = dir.write("l.yaml", lights + "scene: {sphere: {radius: 1}}\n");
  RunResult r = run_sdfc("check " + scene);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.err.find("each light counts as 16 nodes"), std::string::npos) << r.err;
}

TEST(Caps, OnlyRegularFilesOfBoundedSizeAreRead) {
  ScratchDir dir;
  RunResult r = run_sdfc("check /dev/zero");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  std::string big = dir.file("sparse.yaml");
  { std::ofstream(big) << "scene: {sphere: {radius: 1}}\n"; }
  std::filesystem::resize_file(big, 8ull << 30);  // 8 GB, sparse: no disk used
  r = run_sdfc("check " + big, kMemoryLimit);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("scene files are limited to"), std::string::npos) << r.err;
}

TEST(Caps, AHugeStringValueIsRefusedWithAShortMessage) {
  ScratchDir dir;
  for (size_t bytes : {size_t(1) << 20, size_t(100) << 20}) {  // the value cap, then the file cap
    std::string scene =
        dir.write("s.yaml", "scene: {sphere: {radius: 1}, material: \"" + std::string(bytes, 'a') + "\"}\n");
    RunResult r = run_sdfc("check " + scene, kMemoryLimit);
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(bytes < (8u << 20) ? "at most 65536 are allowed" : "scene files are limited to"),
              std::string::npos)
        << r.err.substr(0, 300);
    EXPECT_LT(r.err.size(), 3000u);
  }
}

TEST(Caps, TerminalEscapesInMessagesAreQuoted) {
  ScratchDir dir;
  std::string scene = dir.write("e.yaml", "scene: {sphere: {radius: 1}, material: \"\\e]0;TITLE\\a\\e[2J\"}\n"
                                          "bogus\\e[2J: 1\n");
  RunResult r = run_sdfc("check " + scene);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "a raw ESC reached the terminal";
  EXPECT_EQ(r.err.find('\a'), std::string::npos);
  EXPECT_NE(r.err.find("\\x1b]0;TITLE\\x07"), std::string::npos) << r.err;
  r = run_sdfc("render " + dir.write("ok.yaml", "scene: {sphere: {radius: 1}}\n") + " -q -o " + dir.file("o.png"),
               "SDFC_DEVICE=\"$(printf 'nope\\033[2J')\" ");
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\\x1b[2J"), std::string::npos) << r.err;
}

// compare reads <stem>.depth.pfm beside each PNG: its header must agree
// with its size before anything is allocated, and its scale must say a
// byte order.
TEST(Caps, PfmHeadersAreCheckedAgainstTheFileSize) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", "render: {width: 8, height: 8}\nscene: {sphere: {radius: 1}}\n");
  ASSERT_EQ(run_sdfc("render " + scene + " -q -o " + dir.file("a.png")).code, 0);
  ASSERT_EQ(run_sdfc("render " + scene + " -q -o " + dir.file("b.png")).code, 0);
  dir.write("a.depth.pfm", "Pf\n65536 65536\n-1.0\n" + std::string(12000, '\0'));
  dir.write("b.depth.pfm", "Pf\n8 8\n-1.0\n" + std::string(256, '\0'));
  RunResult r = run_sdfc("compare " + dir.file("a.png") + " " + dir.file("b.png"), kMemoryLimit);
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("truncated (the header says 65536x65536)"), std::string::npos) << r.err;
  for (const char* scale : {"0", "nan", "-nan"}) {  // no byte order: once read as big-endian
    SCOPED_TRACE(scale);
    dir.write("a.depth.pfm", "Pf\n8 8\n" + std::string(scale) + "\n" + std::string(256, '\0'));
    r = run_sdfc("compare " + dir.file("a.png") + " " + dir.file("b.png"));
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.err.find("non-zero"), std::string::npos) << r.err;
  }
}

// A render against itself has no normal error (acos of a rounded dot
// product said 0.036 degrees), and a NaN depth is refused, not read as a miss.
TEST(Caps, CompareOfAFileWithItselfIsExactAndANanDepthIsRefused) {
  ScratchDir dir;
  std::string scene = dir.write("s.yaml", "camera: {position: [0, -4, 1], target: [0, 0, 0]}\n"
                                          "render: {width: 16, height: 16}\nscene: {sphere: {radius: 1}}\n");
  ASSERT_EQ(run_sdfc("render " + scene + " -q --aov depth,normal,hit -o " + dir.file("a.png")).code, 0);
  RunResult r = run_sdfc("compare " + dir.file("a.png") + " " + dir.file("a.png"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("normal error, median / p99       0.000 / 0.000 deg"), std::string::npos) << r.out;
  std::string pfm = "Pf\n16 16\n-1.0\n";
  for (int i = 0; i < 256; ++i) pfm += std::string("\x00\x00\xc0\x7f", 4);  // quiet NaN, little-endian
  for (const char* f : {"b.png", "b.normal.pfm", "b.hit.pfm"})
    std::filesystem::copy_file(dir.file(std::string("a") + (f + 1)), dir.file(f));
  dir.write("b.depth.pfm", pfm);
  r = run_sdfc("compare " + dir.file("a.png") + " " + dir.file("b.png"));
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("holds NaN"), std::string::npos) << r.err;
}

TEST(Caps, PrintableQuotesControlsAndKeepsText) {
  EXPECT_EQ(printable("a\x1b[2Jb\tc\nd\xc2\x9b" "e \xc3\xa9"), "a\\x1b[2Jb\tc\nd\\x9be \xc3\xa9");
  EXPECT_EQ(printable(std::string(10, 'x'), 4), "xxxx... (6 bytes more)");
}

}  // namespace
}  // namespace sdfc::test
