// Camera bookmarks and the hi-res render in the real viewer, driven by SDL
// key events: Shift+digit keeps the view in the scene file (comments and
// the rest of the file kept), the digit recalls it, also in a viewer opened
// later on the saved file; H renders the view to a new PNG beside the scene
// that matches an offline render and never replaces a file.
#include <SDL.h>
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sdfrt/image_io.hpp>
#include <sdfrt/renderer.hpp>
#include <sstream>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/frontend/bookmarks.hpp"
#include "viewer/viewer.hpp"
#include "viewer_test_support.hpp"

namespace sdfc::viewer {
namespace {

namespace fs = std::filesystem;
using test::key;
using test::read_all;
using test::read_png;
using test::step_until;

const std::string kScene =
    "# two shapes (this comment and the layout below must survive)\n"
    "camera: {position: [0, -5, 1], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
    "background: [0.1, 0.1, 0.2]\n"
    "scene:\n"
    "  union:\n"
    "    - sphere: {radius: 0.8}     # left\n"
    "      translate: [-1, 0, 0]\n"
    "    - box: {size: [1, 1, 1]}\n"
    "      translate: [1.2, 0, 0]\n";

struct SceneDir {
  fs::path dir = fs::path(::testing::TempDir()) / ("sdfc_views_" + std::to_string(::getpid()));
  fs::path path = dir / "views.yaml";
  SceneDir() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(path, std::ios::binary) << kScene;
  }
  ~SceneDir() { fs::remove_all(dir); }
};

ViewerOptions small() {
  ViewerOptions opt;
  opt.width = 64;
  opt.height = 48;
  opt.max_samples = 1;
  return opt;
}

bool same_place(const ir::Camera& a, const ir::Camera& b, double tol) {
  for (int i = 0; i < 3; ++i)
    if (std::fabs(a.position[i] - b.position[i]) > tol || std::fabs(a.target[i] - b.target[i]) > tol) return false;
  return true;
}

TEST(ViewTools, BookmarksAreKeptInTheFileAndRecalledOnLoad) {
  SceneDir f;
  ir::Camera elsewhere;
  elsewhere.position = {3, -3, 2};
  elsewhere.target = {0.2, 0, 0};
  std::vector<std::uint8_t> there;
  {
    SceneSession scene(test::device(), {f.path.string(), {}, 16});
    SdlWindow window("sdfc view test", 64, 48);
    Viewer v(scene, window, small());
    ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered; }));
    const ir::Camera start = v.rig().camera();
    key(SDLK_1);  // nothing kept yet: the view stays
    v.step();
    EXPECT_TRUE(same_place(v.rig().camera(), start, 1e-12));

    const std::vector<std::uint8_t> at_start = v.last_image();
    v.rig().reset(elsewhere);
    key(SDLK_3, KMOD_LSHIFT);
    v.step();
    const std::string saved = read_all(f.path);
    ASSERT_EQ(saved.substr(0, kScene.size()), kScene) << "the file before the new section changed";
    EXPECT_NE(saved.find("bookmarks:"), std::string::npos);
    EXPECT_NE(saved.find("- {key: 3, position: [3, -3, 2], target: ["), std::string::npos) << saved;
    EXPECT_EQ(scene.generation(), 1);  // the viewer's own save is not a reload

    key(SDLK_r);  // back to the scene's camera ...
    ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered && same_place(v.rig().camera(), start, 1e-12); }));
    EXPECT_EQ(v.last_image(), at_start);
    key(SDLK_3);  // ... and to the kept view
    ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered && same_place(v.rig().camera(), elsewhere, 1e-9); }));
    there = v.last_image();
    EXPECT_NE(there, at_start);

    key(SDLK_5, KMOD_RSHIFT);  // a second view: the section is rewritten in place, nothing else moves
    v.step();
    const std::string two = read_all(f.path);
    EXPECT_EQ(two.substr(0, kScene.size()), kScene);
    EXPECT_NE(two.find("{key: 3,"), std::string::npos);
    EXPECT_NE(two.find("{key: 5,"), std::string::npos);
    EXPECT_EQ(two.find("bookmarks:"), two.rfind("bookmarks:"));
  }
  // The saved file is a valid scene, and a new viewer on it knows the views.
  EXPECT_NO_THROW(build_module(load_scene_source(f.path.string(), {}), f.path.string()));
  const std::vector<frontend::Bookmark> kept = frontend::bookmarks_of(load_scene_source(f.path.string(), {}));
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].key, 3);
  EXPECT_EQ(kept[0].position, elsewhere.position);  // the shortest text that reads back: exactly the view
  SceneSession scene(test::device(), {f.path.string(), {}, 16});
  SdlWindow window("sdfc view test", 64, 48);
  Viewer v(scene, window, small());
  ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered; }));
  key(SDLK_KP_3);
  ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered && same_place(v.rig().camera(), elsewhere, 1e-9); }));
  EXPECT_EQ(v.last_image(), there);
}

// `sdfc render`'s kernel for the file with `sets`, at `camera`.
std::vector<std::uint8_t> offline(const std::string& path, const std::vector<std::string>& sets, const ir::Camera& camera,
                                  int w, int h) {
  ir::Module m = build_module(load_scene_source(path, sets), path);
  codegen::EmittedKernel k = codegen::emit_opencl(m, {16, false});
  sdfrt::Renderer r(test::device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""});
  m.plan.camera = camera;
  return sdfrt::to_rgb8(r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h));
}

TEST(ViewTools, HiresRenderWritesANewPngBesideTheScene) {
  SceneDir f;
  SceneSession scene(test::device(), {f.path.string(), {}, 16});
  SdlWindow window("sdfc view test", 64, 48);
  Viewer v(scene, window, small());
  ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered; }));
  ViewTools& tools = v.tools();
  tools.hires_width = 120;
  tools.hires_height = 80;
  tools.hires_samples = 4;
  // A file that holds the second name already: it must stay as it is.
  const fs::path taken = f.dir / "views-120x80-2.png";
  std::ofstream(taken) << "not mine";

  auto render = [&] {
    key(SDLK_h);
    v.step();
    EXPECT_TRUE(tools.hires().running() || !tools.hires().written().empty());
    return step_until(v, [&] { return !tools.hires().running(); });
  };
  ASSERT_TRUE(render());
  const std::string first = tools.hires().written();
  ASSERT_EQ(fs::path(first), f.dir / "views-120x80.png") << tools.hires().status();
  EXPECT_EQ(tools.hires().progress(), 1.0);
  int w = 0, h = 0;
  const std::vector<std::uint8_t> png = read_png(first, w, h);
  ASSERT_EQ(w, 120);
  ASSERT_EQ(h, 80);
  EXPECT_EQ(png, offline(f.path.string(), {"render.samples=4"}, v.rig().camera(), 120, 80));

  const std::string bytes = read_all(first);
  ASSERT_TRUE(render());
  EXPECT_EQ(fs::path(tools.hires().written()), f.dir / "views-120x80-3.png") << tools.hires().status();
  EXPECT_EQ(read_all(first), bytes);
  EXPECT_EQ(read_all(taken), "not mine");
  for (const auto& e : fs::directory_iterator(f.dir))  // no temporary file left behind
    EXPECT_EQ(e.path().filename().string().find(".sdfc-hires"), std::string::npos) << e.path();
}

}  // namespace
}  // namespace sdfc::viewer
