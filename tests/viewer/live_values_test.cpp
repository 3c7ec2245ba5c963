// The panel's model on real kernels: a change of an unlocked value is a new
// frame without a build; after bake() the picture is the baked kernel's; a
// value that shapes the code rebuilds; save edits only the changed numbers
// and undo restores the file byte for byte.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sdfrt/device.hpp>
#include <sdfrt/renderer.hpp>
#include <sstream>
#include <thread>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/compile.hpp"
#include "viewer/live_values.hpp"
#include "viewer_test_support.hpp"

namespace sdfc::viewer {
namespace {

namespace fs = std::filesystem;

using test::device;
using test::read_all;

const std::string kScene =
    "# a sphere beside a box (comments and spacing must survive a save)\n"
    "camera: {position: [0, -6, 2], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
    "lights:\n"
    "  - point: {position: [2, -3, 3], intensity: 6}   # the key light\n"
    "  - directional: {direction: [-0.3, 0.5, -0.8], intensity: 0.6}\n"
    "scene:\n"
    "  union:\n"
    "    - sphere: {radius: 0.8}\n"
    "      translate: [-1, 0, 0]\n"
    "    - box: {size: [1, 1, 1]}\n"
    "      translate: [1.5, 0, 0]\n";

constexpr int kW = 96, kH = 64;

struct SceneFile {
  fs::path dir = fs::temp_directory_path() / ("sdfc_live_" + std::to_string(::getpid()));
  fs::path path = dir / "scene.yaml";
  SceneFile() {
    fs::create_directories(dir);
    std::ofstream(path, std::ios::binary) << kScene;
  }
  ~SceneFile() { fs::remove_all(dir); }
};

sdfrt::FloatImage frame(SceneSession& s, double* ms = nullptr) {
  sdfrt::RenderStats st;
  sdfrt::FloatImage img = s.render(s.module().plan.camera, kW, kH, 0, 0, 0, &st);
  if (ms) *ms = st.total_ms;
  return img;
}

// The scene file's own kernel with `sets` baked, as `sdfc render --set` builds it.
sdfrt::FloatImage baked(const fs::path& path, const std::vector<std::string>& sets) {
  ir::Module m = build_module(load_scene_source(path.string(), sets), path.string());
  codegen::EmittedKernel k = codegen::emit_opencl(m, {8, false});
  sdfrt::Renderer r(device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, ""});
  return r.render(codegen::frame_params(m.plan, kW, kH, 0.0), kW, kH);
}

double max_difference(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) worst = std::max(worst, double(std::fabs(a.at(c, x, y) - b.at(c, x, y))));
  return worst;
}

// The share of pixels with a colour channel more than 1/255 apart. The
// unlocked kernel's bounds hold for the slider's whole range, so its march
// is clipped to a larger box and grazing hits move a little (tests/unlock).
double share_apart(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  int apart = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      bool off = false;
      for (int c = 0; c < 3; ++c) off = off || std::fabs(a.at(c, x, y) - b.at(c, x, y)) > 1.0 / 255;
      apart += off;
    }
  return double(apart) / (kW * kH);
}

bool wait_for_build(LiveValues& live) {
  auto t0 = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120)) {
    if (live.poll() == ReloadResult::Reloaded) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST(LiveValues, SliderMovesAreFramesAndBakingGivesTheBakedPicture) {
  SceneFile f;
  SceneSession scene(device(), {f.path.string(), {}, 8});
  LiveValues live(scene);
  const std::string radius = "scene.union[0].sphere.radius";
  EXPECT_EQ(live.set(radius, 0.9), LiveValues::Change::Unlocking);
  ASSERT_TRUE(wait_for_build(live)) << scene.error();
  const double unlock_ms = scene.last_build_ms();
  EXPECT_EQ(scene.builds(), 2);
  ASSERT_EQ(scene.slots().size(), 1u);
  const sdfrt::FloatImage at_09 = frame(scene);

  EXPECT_EQ(live.set(radius, 1.2), LiveValues::Change::Frame);
  double live_ms = 0;
  const sdfrt::FloatImage at_12 = frame(scene, &live_ms);
  EXPECT_EQ(scene.builds(), 2);  // no build for the slider move
  EXPECT_GT(max_difference(at_09, at_12), 0.1);
  EXPECT_LE(share_apart(at_12, baked(f.path, {"scene.union.0.sphere.radius=1.2"})), 0.05);

  live.bake();
  ASSERT_TRUE(wait_for_build(live)) << scene.error();
  EXPECT_TRUE(scene.slots().empty());
  EXPECT_EQ(scene.builds(), 3);
  double baked_ms = 0;
  frame(scene);  // the first launch of a new kernel compiles its work-group function
  const sdfrt::FloatImage rebaked = frame(scene, &baked_ms);
  EXPECT_LE(max_difference(rebaked, baked(f.path, {"scene.union.0.sphere.radius=1.2"})), 1.0 / 255);
  frame(scene);
  // Reported, not asserted: the unlocked and the baked kernel's frame times.
  std::cout << "unlock build " << unlock_ms << " ms; frame unlocked " << live_ms << " ms, baked " << baked_ms
            << " ms (" << kW << "x" << kH << ")\n";
}

TEST(LiveValues, ValuesThatShapeTheCodeRebuild) {
  SceneFile f;
  std::ofstream(f.path, std::ios::app) << "render: {max_steps: 200}\n";
  SceneSession scene(device(), {f.path.string(), {}, 8});
  LiveValues live(scene);
  EXPECT_EQ(live.set("render.max_steps", 64), LiveValues::Change::Rebuilding);
  ASSERT_TRUE(wait_for_build(live)) << scene.error();
  EXPECT_EQ(scene.builds(), 2);
  EXPECT_TRUE(scene.slots().empty());
}

TEST(LiveValues, SaveChangesOnlyTheEditedNumbersAndUndoRestoresTheFile) {
  SceneFile f;
  SceneSession scene(device(), {f.path.string(), {}, 8});
  LiveValues live(scene);
  EXPECT_EQ(live.save(), LiveValues::Saved::NothingToSave);
  live.set("scene.union[0].sphere.radius", 1.25);
  live.set("lights[0].point.intensity", 4.5);
  EXPECT_TRUE(live.changed("scene.union.0.sphere.radius"));
  ASSERT_EQ(live.save(), LiveValues::Saved::Written);
  std::string expected = kScene;
  expected.replace(expected.find("radius: 0.8") + 8, 3, "1.25");
  expected.replace(expected.find("intensity: 6") + 11, 1, "4.5");
  EXPECT_EQ(read_all(f.path), expected);
  EXPECT_FALSE(live.changed("scene.union.0.sphere.radius"));

  EXPECT_TRUE(live.undo());
  EXPECT_TRUE(live.undo());
  EXPECT_FALSE(live.undo());
  ASSERT_EQ(live.save(), LiveValues::Saved::Written);
  EXPECT_EQ(read_all(f.path), kScene);
  EXPECT_TRUE(live.redo());
  EXPECT_EQ(live.value("scene.union.0.sphere.radius"), 1.25);

  // Someone else edits the file: the first save refuses, the second (confirmed) writes.
  std::ofstream(f.path, std::ios::binary) << kScene << "# edited elsewhere\n";
  EXPECT_EQ(live.save(), LiveValues::Saved::ChangedOnDisk);
  EXPECT_EQ(read_all(f.path), kScene + "# edited elsewhere\n");
  EXPECT_EQ(live.save(true), LiveValues::Saved::Written);
  EXPECT_NE(read_all(f.path).find("radius: 1.25"), std::string::npos);
}

// A checkbox: true/false shapes the code, so it rebuilds; it is saved as the word.
TEST(LiveValues, BooleansRebuildAndAreSavedAsWords) {
  SceneFile f;
  std::ofstream(f.path, std::ios::app) << "render: {dither: false, max_steps: 200}\n";
  const std::string original = read_all(f.path);
  SceneSession scene(device(), {f.path.string(), {}, 8});
  LiveValues live(scene);
  EXPECT_EQ(live.value("render.dither"), 0);
  EXPECT_EQ(live.set_bool("render.dither", true), LiveValues::Change::Rebuilding);
  ASSERT_TRUE(wait_for_build(live)) << scene.error();
  EXPECT_TRUE(scene.module().plan.march.dither);
  EXPECT_TRUE(live.changed("render.dither"));
  ASSERT_EQ(live.save(), LiveValues::Saved::Written);
  std::string expected = original;
  expected.replace(expected.find("dither: false") + 8, 5, "true");
  EXPECT_EQ(read_all(f.path), expected);
  EXPECT_TRUE(live.undo());
  ASSERT_EQ(live.save(), LiveValues::Saved::Written);
  EXPECT_EQ(read_all(f.path), original);
}

}  // namespace
}  // namespace sdfc::viewer
