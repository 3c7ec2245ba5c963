// The live viewer end to end: a real SDL window (Xvfb or the offscreen
// driver), real kernels on PoCL. The P key's screenshot must equal an
// offline render; saving the scene swaps the kernel; a broken save keeps it.
#include <SDL.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sdfrt/device.hpp>
#include <sdfrt/image_io.hpp>
#include <sdfrt/renderer.hpp>
#include <sstream>
#include <thread>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "viewer/viewer.hpp"
#include "viewer_test_support.hpp"

namespace sdfc::viewer {
namespace {

namespace fs = std::filesystem;

using test::device;
using test::step_until;
using test::read_png;
constexpr auto press = [](SDL_Keycode k) { test::key(k); };

// The same kernel `sdfc render` builds, rendered offline at `camera`.
std::vector<std::uint8_t> offline_render(const std::string& path, const ir::Camera& camera, int w, int h) {
  ir::Module m = build_module(load_scene_source(path, {}), path);
  codegen::EmittedKernel k = codegen::emit_opencl(m, {16, false});
  sdfrt::Renderer r(device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""});
  m.plan.camera = camera;
  return sdfrt::to_rgb8(r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h));
}

// Mean of the `steps` AOV of the same render, from a kernel built with AOVs.
double offline_mean_steps(const std::string& path, const ir::Camera& camera, int w, int h) {
  ir::Module m = build_module(load_scene_source(path, {}), path);
  codegen::EmitOptions eo;
  eo.simd_width = 16;
  eo.aovs = true;
  codegen::EmittedKernel k = codegen::emit_opencl(m, eo);
  sdfrt::Renderer r(device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""});
  m.plan.camera = camera;
  sdfrt::FloatImage img = r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h);
  double sum = 0;
  for (float s : img.plane(img.plane_index("steps"))) sum += s;
  return sum / double(img.plane_size());
}

void write_file(const fs::path& p, const std::string& text) {
  // Through a rename, as editors save, so the viewer never sees half a file.
  fs::path tmp = p.string() + ".tmp";
  std::ofstream(tmp) << text;
  fs::rename(tmp, p);
}

const char* kRedSphere = R"(camera: {position: [0, -4, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}
background: [0, 0, 0]
lights:
  - ambient: {color: [1, 1, 1], intensity: 1}
materials:
  red: {color: [1, 0, 0]}
scene:
  sphere: {radius: 1}
  material: red
)";

const char* kGreenBox = R"(camera: {position: [0, -4, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}
background: [0, 0, 0]
lights:
  - ambient: {color: [1, 1, 1], intensity: 1}
materials:
  green: {color: [0, 1, 0]}
scene:
  box: {size: [1.6, 1.6, 1.6]}
  material: green
)";


std::array<int, 3> centre_pixel(const Viewer& v) {
  const auto& img = v.last_image();
  const FrameInfo& f = v.last_frame();
  std::size_t i = (std::size_t(f.height / 2) * f.width + f.width / 2) * 3;
  return {img[i], img[i + 1], img[i + 2]};
}

TEST(Viewer, ScreenshotFromThePKeyMatchesAnOfflineRender) {
  const std::string scene_path = std::string(SDFC_SOURCE_DIR) + "/examples/mandelbulb.yaml";
  SceneSession scene(device(), {scene_path, {}, 16});
  ViewerOptions opt;
  opt.width = 192;
  opt.height = 108;
  opt.max_samples = 2;
  opt.screenshot_dir = SDFC_VIEWER_SHOT_DIR;
  fs::remove_all(opt.screenshot_dir);  // keep only this run's screenshot there
  fs::create_directories(opt.screenshot_dir);
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);

  // Fly a little so the screenshot is not just the scene's own camera.
  MotionInput in;
  in.forward = 1;
  in.right = 0.5;
  in.yaw = 0.15;
  v.rig().apply(in, 0.25, scene.distance_at(v.rig().position()));
  ASSERT_TRUE(v.step());
  EXPECT_TRUE(v.last_frame().rendered);
  EXPECT_EQ(v.last_frame().width, opt.width);
  EXPECT_EQ(v.last_frame().samples, 1);
  // F1's steps/pixel is the mean of the kernel's steps AOV for that frame.
  const double steps = offline_mean_steps(scene_path, v.rig().camera(), opt.width, opt.height);
  EXPECT_GT(steps, 1.0);
  EXPECT_NEAR(v.last_frame().steps, steps, 0.005 * steps);
  ASSERT_TRUE(v.step());
  EXPECT_EQ(v.last_frame().samples, 2);  // refines with a second sample when still

  press(SDLK_p);
  ASSERT_TRUE(v.step());
  ASSERT_FALSE(v.last_screenshot().empty());
  EXPECT_EQ(fs::path(v.last_screenshot()).parent_path(), fs::path(SDFC_VIEWER_SHOT_DIR));
  int w = 0, h = 0;
  std::vector<std::uint8_t> shot = read_png(v.last_screenshot(), w, h);
  ASSERT_EQ(w, opt.width);
  ASSERT_EQ(h, opt.height);
  std::vector<std::uint8_t> ref = offline_render(scene_path, v.rig().camera(), w, h);
  ASSERT_EQ(shot.size(), ref.size());
  int worst = 0, lit = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    worst = std::max(worst, std::abs(int(shot[i]) - int(ref[i])));
    lit += shot[i] > 0;
  }
  EXPECT_LE(worst, 1) << "screenshot and offline render differ by more than 1/255";
  std::cerr << "screenshot " << v.last_screenshot() << ": largest difference to the offline render " << worst
            << "/255\n";
  EXPECT_GT(lit, int(ref.size() / 2));  // a real picture, not a black frame

  // C prints the camera as a scene line; F1 turns the stats on.
  ::testing::internal::CaptureStdout();
  press(SDLK_c);
  ASSERT_TRUE(v.step());
  std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(printed.rfind("camera: {position: [", 0), 0u) << printed;
  press(SDLK_F1);
  ASSERT_TRUE(v.step());
  EXPECT_TRUE(v.overlay());
  EXPECT_NE(window.title().find("fps"), std::string::npos) << window.title();
  EXPECT_NE(window.title().find(fmt::format("{:.1f} steps/pixel", v.last_frame().steps)), std::string::npos)
      << window.title();

  press(SDLK_ESCAPE);
  EXPECT_FALSE(v.step());
}

TEST(Viewer, MouseLookRendersSmallThenRefinesToFullResolution) {
  const std::string scene_path = std::string(SDFC_SOURCE_DIR) + "/examples/primitives.yaml";
  SceneSession scene(device(), {scene_path, {}, 16});
  ViewerOptions opt;
  opt.width = 192;
  opt.height = 96;
  opt.max_samples = 1;
  opt.frame_budget_ms = 1e-6;  // no frame fits: the smallest scale, 1/8
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);
  ASSERT_TRUE(v.step());  // calibrates the cost per pixel
  const ir::Camera before = v.rig().camera();

  SDL_Event e{};
  e.type = SDL_MOUSEMOTION;
  e.motion.state = SDL_BUTTON_LMASK;
  e.motion.xrel = 40;
  e.motion.yrel = -10;
  ASSERT_EQ(SDL_PushEvent(&e), 1);
  ASSERT_TRUE(v.step());
  EXPECT_NE(v.rig().camera().target, before.target);
  EXPECT_EQ(v.rig().camera().position, before.position);  // looking turns, it does not move
  EXPECT_EQ(v.last_frame().divisor, 8);
  EXPECT_EQ(v.last_frame().width, opt.width / 8);
  EXPECT_EQ(v.last_frame().samples, 0);

  ASSERT_TRUE(v.step());  // still again: full resolution
  EXPECT_EQ(v.last_frame().divisor, 1);
  EXPECT_EQ(v.last_frame().width, opt.width);
  EXPECT_EQ(v.last_frame().samples, 1);
}

TEST(Viewer, SavingTheSceneSwapsTheKernelAndKeepsTheCamera) {
  fs::path path = fs::path(::testing::TempDir()) / "viewer_reload.yaml";
  write_file(path, kRedSphere);
  SceneSession scene(device(), {path.string(), {}, 16});
  ViewerOptions opt;
  opt.width = 64;
  opt.height = 48;
  opt.max_samples = 1;
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);
  MotionInput in;
  in.forward = 1;
  v.rig().apply(in, 0.1, 1.0);
  const ir::Camera moved = v.rig().camera();
  ASSERT_TRUE(v.step());
  auto before = centre_pixel(v);
  EXPECT_GT(before[0], 200);
  EXPECT_EQ(before[1], 0);

  write_file(path, kGreenBox);
  ASSERT_TRUE(step_until(v, [&] { return scene.generation() == 2; })) << scene.error();
  ASSERT_TRUE(v.last_frame().rendered);  // the reload restarts the refinement
  auto after = centre_pixel(v);
  EXPECT_EQ(after[0], 0);
  EXPECT_GT(after[1], 200);
  EXPECT_TRUE(scene.error().empty());
  EXPECT_EQ(v.rig().camera().position, moved.position);
}

TEST(Viewer, ABrokenSaveKeepsTheOldKernelAndReportsTheError) {
  fs::path path = fs::path(::testing::TempDir()) / "viewer_broken.yaml";
  write_file(path, kRedSphere);
  SceneSession scene(device(), {path.string(), {}, 16});
  ViewerOptions opt;
  opt.width = 64;
  opt.height = 48;
  opt.max_samples = 1;
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);
  ASSERT_TRUE(v.step());
  const std::vector<std::uint8_t> good = v.last_image();

  std::string broken = kRedSphere;
  broken.replace(broken.find("sphere:"), 7, "sphear:");
  write_file(path, broken);
  ASSERT_TRUE(step_until(v, [&] { return !scene.error().empty(); }));
  EXPECT_EQ(scene.generation(), 1);
  // file:line:col and a suggestion, in the window title too.
  EXPECT_NE(scene.error().find("viewer_broken.yaml:8:"), std::string::npos) << scene.error();
  EXPECT_NE(scene.error().find("sphere"), std::string::npos) << scene.error();
  EXPECT_NE(window.title().find("ERROR"), std::string::npos) << window.title();
  EXPECT_NE(window.title().find("viewer_broken.yaml:8:"), std::string::npos) << window.title();

  // The old kernel still renders: move and come back, the picture is the same.
  press(SDLK_r);
  ASSERT_TRUE(v.step());
  ASSERT_TRUE(v.last_frame().rendered);
  EXPECT_EQ(v.last_image(), good);

  // Fixing the file clears the error.
  write_file(path, kGreenBox);
  ASSERT_TRUE(step_until(v, [&] { return scene.generation() == 2; })) << scene.error();
  EXPECT_TRUE(scene.error().empty());
  EXPECT_EQ(window.title().find("ERROR"), std::string::npos) << window.title();
}

TEST(Viewer, AStillFrameIsAbandonedBetweenTilesWhenInputArrives) {
  const std::string scene_path = std::string(SDFC_SOURCE_DIR) + "/examples/primitives.yaml";
  SceneSession scene(device(), {scene_path, {}, 16});
  const ir::Camera cam = scene.module().plan.camera;
  int asked = 0;
  auto after_two_tiles = [&] { return ++asked > 2; };
  // 600x300: six tiles of the CPU's 256 pixels (more of other devices' 128x64).
  EXPECT_FALSE(scene.render_interruptible(cam, 600, 300, 0.0, 0, 0, after_two_tiles).has_value());
  EXPECT_EQ(asked, 3);  // asked before the first tile, after the first and after the second
  auto never = [] { return false; };
  auto full = scene.render_interruptible(cam, 600, 300, 0.0, 0, 0, never);
  ASSERT_TRUE(full.has_value());
  EXPECT_EQ(sdfrt::to_rgb8(*full), sdfrt::to_rgb8(scene.render(cam, 600, 300, 0.0)));
}

// `sdfc view --benchmark` through the real binary: the built-in orbit for a
// scene without a camera path, the scene's path for examples/flythrough.yaml.
TEST(Viewer, BenchmarkPrintsFrameStatistics) {
  struct Case {
    const char* scene;
    const char* camera;
  } cases[] = {{"examples/primitives.yaml", "benchmark: orbiting the target by 360 degrees"},
               {"examples/flythrough.yaml", "benchmark: playing camera.path (5 keys, 4.00 s"}};
  for (const Case& c : cases) {
    std::string out = ::testing::TempDir() + "/viewer_benchmark.txt", err = ::testing::TempDir() + "/viewer_benchmark.err";
    std::string cmd = std::string("cd ") + SDFC_SOURCE_DIR + " && " + SDFC_BINARY + " view " + c.scene +
                      " --width 64 --height 36 --benchmark 1 >" + out + " 2>" + err;
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << c.scene;
    std::stringstream ss, es;
    ss << std::ifstream(out).rdbuf();
    es << std::ifstream(err).rdbuf();
    std::string text = ss.str();
    EXPECT_NE(es.str().find(c.camera), std::string::npos) << es.str();
    for (const char* field : {"benchmark: 64x36", "frames", "mean", "min", "max", "1% low", "fps"})
      EXPECT_NE(text.find(field), std::string::npos) << field << " missing in:\n" << text;
    auto at = text.find("frames");
    ASSERT_NE(at, std::string::npos);
    int frames = std::stoi(text.substr(at + 6));
    EXPECT_GT(frames, 1) << c.scene;
  }
}

// The benchmark moves the camera along the scene's path: its last frame
// is the path at a later time, not the first key.
TEST(Viewer, BenchmarkPlaysTheScenesCameraPath) {
  const std::string scene_path = std::string(SDFC_SOURCE_DIR) + "/examples/flythrough.yaml";
  SceneSession scene(device(), {scene_path, {}, 16});
  ASSERT_FALSE(scene.module().plan.camera.path.empty());
  ViewerOptions opt;
  opt.width = 64;
  opt.height = 36;
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);
  FrameStats st = v.benchmark(1.0);
  EXPECT_GT(st.frames, 1);
  const ir::Camera path_camera = scene.module().plan.camera;
  std::vector<std::uint8_t> first = sdfrt::to_rgb8(scene.render(path_camera, opt.width, opt.height, 0.0));
  ASSERT_EQ(v.last_image().size(), first.size());
  EXPECT_NE(v.last_image(), first) << "the camera did not move along the path";
}

}  // namespace
}  // namespace sdfc::viewer
