// `sdfc view --events`: the real binary in a real window, driven by a script
// of SDL key presses and panel edits. One session opens the panel, changes a
// radius, saves with Ctrl+S, keeps a view with Shift+2, renders the view
// with H and snaps the window; the file afterwards is the original with
// exactly the radius's characters changed and the bookmarks section added.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <string>

#include "run_sdfc.hpp"

namespace sdfc::test {
namespace {

const std::string kScene =
    "# a sphere on its own (this comment must survive)\n"
    "camera: {position: [0, -4, 1], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
    "render: {width: 96, height: 64}\n"
    "background: [0.2, 0.2, 0.3]\n"
    "scene:\n"
    "  sphere: {radius: 1}   # the slider\n";

bool png_size(const std::string& path, int* w, int* h) {
  int channels = 0;
  return stbi_info(path.c_str(), w, h, &channels) == 1;
}

TEST(ViewEvents, AScriptedSessionEditsSavesKeepsAViewAndRendersIt) {
  ScratchDir dir;
  const std::string scene = dir.write("ball.yaml", kScene);
  const std::string script = dir.write("session.events",
                                       "# the panel, a live change, a save, a kept view, a hi-res render\n"
                                       "key F2\n"
                                       "settle\n"
                                       "set scene.sphere.radius 0.75\n"
                                       "settle\n"
                                       "snap " + dir.file("window.png") + "\n"
                                       "key ctrl+s\n"
                                       "key shift+2\n"
                                       "hires 160 100 2\n"
                                       "key h\n"
                                       "settle\n"
                                       "quit\n");
  RunResult r = run_sdfc("view " + scene + " --samples 1 --events " + script);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("view 2 kept in"), std::string::npos) << r.err;

  const std::string saved = read_text(scene);
  std::string expected = kScene;
  expected.replace(expected.find("radius: 1") + 8, 1, "0.75");
  ASSERT_EQ(saved.substr(0, expected.size()), expected) << saved;
  EXPECT_EQ(saved.substr(expected.size()).rfind("bookmarks:", 0), 0u) << saved;
  EXPECT_NE(saved.find("- {key: 2, position: [0, -4, 1]"), std::string::npos) << saved;
  RunResult check = run_sdfc("check " + scene);
  EXPECT_EQ(check.code, 0) << check.err;

  int w = 0, h = 0;
  ASSERT_TRUE(png_size(dir.file("window.png"), &w, &h));
  EXPECT_EQ(w, 96);
  EXPECT_EQ(h, 64);
  ASSERT_TRUE(png_size(dir.file("ball-160x100.png"), &w, &h)) << r.err;
  EXPECT_EQ(w, 160);
  EXPECT_EQ(h, 100);
}

TEST(ViewEvents, ABadScriptIsRefusedWithItsLine) {
  ScratchDir dir;
  const std::string scene = dir.write("ball.yaml", kScene);
  const std::string script = dir.write("bad.events", "key F2\nsettel\n");
  RunResult r = run_sdfc("view " + scene + " --events " + script);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("bad.events:2:1: error: unknown command 'settel'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'settle'"), std::string::npos) << r.err;
  EXPECT_NE(run_sdfc("view --help").out.find("--events"), std::string::npos);
}

}  // namespace
}  // namespace sdfc::test
