// The command line's own words: --version, suggestions for a mistyped
// command or option, plain progress unless --verbose, --samples, --frames
// checked first, --fit.
#include <gtest/gtest.h>

#include <filesystem>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::run_sdfc;

TEST(CliWords, VersionPrintsTheProjectVersion) {
  auto r = run_sdfc("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("sdfc 0.", 0), 0u) << r.out;
}

TEST(CliWords, MistypedCommandOrOptionGetsASuggestion) {
  auto r = run_sdfc("rendr examples/primitives.yaml -o x.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("'rendr' is not a command; did you mean 'render'?"), std::string::npos) << r.err;
  r = run_sdfc("render examples/primitives.yaml -o x.png --widht 64");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("did you mean '--width'?"), std::string::npos) << r.err;
  r = run_sdfc("check examples/primitives.yaml --sett render.width=3");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("did you mean '--set'?"), std::string::npos) << r.err;
}

TEST(CliWords, RenderSpeaksPlainlyUnlessVerbose) {
  sdfc::test::ScratchDir dir;
  std::string out = dir.path() + "/p.png";
  auto plain = run_sdfc("render examples/primitives.yaml --width 64 --height 36 --samples 2 -o " + out);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.err.find("rendering on "), std::string::npos) << plain.err;
  EXPECT_EQ(plain.err.find("work-item"), std::string::npos) << plain.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  auto verbose = run_sdfc("render examples/primitives.yaml --width 64 --height 36 --verbose -o " + out);
  ASSERT_EQ(verbose.code, 0) << verbose.err;
  EXPECT_NE(verbose.err.find("pixel(s) per work-item"), std::string::npos) << verbose.err;
  EXPECT_EQ(run_sdfc("render examples/primitives.yaml --samples 0 -o " + out).code, 2);
}

TEST(CliWords, BadFramesAreRefusedBeforeTheKernelBuilds) {
  // OCL_ICD_VENDORS pointing nowhere: had render opened a device, it would
  // fail with a device error (exit 3) instead of the usage message.
  for (const char* frames : {"abc", "5:2", "0:10:0"}) {
    auto r = run_sdfc(std::string("render examples/primitives.yaml -o x.png --frames ") + frames,
                      "OCL_ICD_VENDORS=/nonexistent ");
    EXPECT_NE(r.err.find("--frames"), std::string::npos) << frames << ": " << r.err;
    EXPECT_EQ(r.err.find("rendering on"), std::string::npos) << frames << ": " << r.err;
    EXPECT_NE(r.code, 3) << frames << ": " << r.err;
  }
}

TEST(CliWords, FitIsAnOptionOfRenderAndCheckPrintsWhereTheCameraGoes) {
  auto r = run_sdfc("check examples/kifs.yaml --set camera.fit=true");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("camera fit: frames ["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("position ["), std::string::npos) << r.out;
  auto help = run_sdfc("render --help");
  EXPECT_NE(help.out.find("--fit"), std::string::npos) << help.out;
}

}  // namespace
