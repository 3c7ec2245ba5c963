// The F2 panel in the real viewer, driven by SDL events: F2 opens it, a
// change of an unlocked value draws new frames without a build, Ctrl+Z
// undoes it, and after the idle time the values are baked again.
#include <SDL.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sdfrt/device.hpp>
#include <thread>

#include "viewer/viewer.hpp"
#include "viewer_test_support.hpp"

namespace sdfc::viewer {
namespace {

namespace fs = std::filesystem;

const char* kSphere = R"(camera: {position: [0, -4, 0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}
background: [0, 0, 0]
lights:
  - ambient: {color: [1, 1, 1], intensity: 1}
scene:
  sphere: {radius: 1}   # the panel's slider
)";

using test::key;
using test::step_until;

TEST(Panel, LiveChangesUndoAndTheIdleBake) {
  sdfrt::Device& device = test::device();
  fs::path path = fs::path(::testing::TempDir()) / "panel_sphere.yaml";
  std::ofstream(path) << kSphere;
  SceneSession scene(device, {path.string(), {}, 16});
  ViewerOptions opt;
  opt.width = 64;
  opt.height = 48;
  opt.max_samples = 1;
  SdlWindow window("sdfc view test", opt.width, opt.height);
  Viewer v(scene, window, opt);
  ASSERT_TRUE(step_until(v, [&] { return v.last_frame().rendered; }));
  const std::vector<std::uint8_t> original = v.last_image();

  key(SDLK_F2);
  ASSERT_TRUE(v.step());
  EXPECT_TRUE(v.panel_shown());
  LiveValues& live = v.live_values();
  EXPECT_EQ(live.set("scene.sphere.radius", 0.5), LiveValues::Change::Unlocking);
  ASSERT_TRUE(step_until(v, [&] { return scene.generation() == 2; })) << scene.error();
  ASSERT_TRUE(v.last_frame().rendered);  // the new kernel draws in the step that swaps it in
  const std::vector<std::uint8_t> small = v.last_image();
  EXPECT_NE(small, original);
  EXPECT_EQ(scene.builds(), 2);

  key(SDLK_z, KMOD_LCTRL);  // back to radius 1: inside the slot's range, so a frame, not a build
  ASSERT_TRUE(step_until(v, [&] { return live.value("scene.sphere.radius") == 1.0 && v.last_frame().rendered; }));
  EXPECT_EQ(scene.builds(), 2);
  EXPECT_FALSE(scene.slots().empty());
  EXPECT_NE(v.last_image(), small);

  // Left alone, the panel bakes the values: the kernel is the file's own again.
  ASSERT_TRUE(step_until(v, [&] { return scene.slots().empty() && scene.generation() == 3; })) << scene.error();
  ASSERT_TRUE(v.last_frame().rendered);
  EXPECT_EQ(scene.builds(), 3);
  EXPECT_EQ(v.last_image(), original);
  key(SDLK_F2);
  ASSERT_TRUE(v.step());
  EXPECT_FALSE(v.panel_shown());
}

}  // namespace
}  // namespace sdfc::viewer
