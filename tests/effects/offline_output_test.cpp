// sdfc render's offline outputs as a user runs them: AOVs beside the image,
// 16-bit PNG, progressive samples, sequences from one kernel build.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <tuple>

#include "run_sdfc.hpp"

namespace {

namespace fs = std::filesystem;

using Result = sdfc::test::RunResult;

std::string slurp(const fs::path& path) { return sdfc::test::read_text(path.string()); }

class OfflineOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / ("sdfc_offline_" + std::to_string(getpid()) + "_" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result sdfc(const std::string& args) { return sdfc::test::run_sdfc(args); }
  std::string scene(const std::string& text) {
    fs::path p = dir_ / "scene.yaml";
    std::ofstream(p) << text;
    return p.string();
  }
  fs::path dir_;
};

// Pixels of an 8-bit RGB PNG.
std::vector<unsigned char> load_rgb8(const fs::path& p, int* w, int* h) {
  int n = 0;
  unsigned char* data = stbi_load(p.string().c_str(), w, h, &n, 3);
  if (!data) return {};
  std::vector<unsigned char> v(data, data + static_cast<size_t>(*w) * *h * 3);
  stbi_image_free(data);
  return v;
}

// How many times a render's stderr says a kernel was built.
size_t kernel_builds(const std::string& err) {
  size_t builds = 0;
  for (size_t at = err.find("kernel built"); at != std::string::npos; at = err.find("kernel built", at + 1)) ++builds;
  return builds;
}

// Frames 0..2 of a sequence written as DIR/f_0N.png: each must load and
// differ from the other two.
void expect_three_different_frames(const fs::path& dir) {
  std::vector<std::vector<unsigned char>> frames;
  for (int i = 0; i < 3; ++i) {
    int w = 0, h = 0;
    frames.push_back(load_rgb8(dir / ("f_0" + std::to_string(i) + ".png"), &w, &h));
    ASSERT_FALSE(frames.back().empty()) << i;
  }
  EXPECT_NE(frames[0], frames[1]);
  EXPECT_NE(frames[1], frames[2]);
  EXPECT_NE(frames[0], frames[2]);
}

TEST_F(OfflineOutput, AovsBesideASixteenBitPng) {
  std::string s = scene("render: {width: 40, height: 30}\ncamera: {position: [0, -5, 0], target: [0, 0, 0]}\n"
                        "scene: {sphere: {radius: 1}}\n");
  Result r = sdfc("render " + s + " -o " + (dir_ / "img.png").string() + " --aov depth,normal,steps,material --bit-depth 16 -q");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(stbi_is_16_bit((dir_ / "img.png").string().c_str()));
  for (const char* aov : {"depth", "normal", "steps", "material"}) {
    fs::path p = dir_ / (std::string("img.") + aov + ".pfm");
    ASSERT_TRUE(fs::exists(p)) << p;
    std::string bytes = slurp(p);
    int channels = std::string(aov) == "normal" ? 3 : 1;
    std::string header = std::string(channels == 3 ? "PF" : "Pf") + "\n40 30\n-1.0\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header) << aov;
    ASSERT_EQ(bytes.size(), header.size() + 40u * 30u * channels * sizeof(float)) << aov;
    if (std::string(aov) == "depth") {
      // PFM rows run bottom-up.
      float d;
      std::memcpy(&d, bytes.data() + header.size() + ((30 - 1 - 15) * 40 + 20) * sizeof(float), sizeof d);
      // Pixel (20, 15) looks 0.0975 off the axis at the sphere: analytic 4.004;
      // the march stops within hit_epsilon * footprint = 0.055 before it.
      EXPECT_LE(d, 4.005f);
      EXPECT_GE(d, 4.004f - 0.056f);
      float corner;
      std::memcpy(&corner, bytes.data() + header.size(), sizeof corner);
      EXPECT_EQ(corner, -1.0f);  // a miss
    }
  }
  EXPECT_NE(r.out.find("img.normal.pfm"), std::string::npos) << r.out;
}

TEST_F(OfflineOutput, ProgressivePassesMatchOneLaunchAndBandsMatchTiles) {
  std::string s = scene("render: {width: 64, height: 48, samples: 4, filter: tent}\n"
                        "camera: {position: [2, -4, 2], target: [0, 0, 0.4]}\n"
                        "scene:\n  union:\n    - plane: {}\n    - sphere: {radius: 0.6}\n      translate: [0, 0, 0.6]\n");
  // --repeat renders every sample in one launch; the default refines pass by pass.
  ASSERT_EQ(sdfc("render " + s + " -o " + (dir_ / "one.png").string() + " --repeat 1 -q").code, 0);
  Result r = sdfc("render " + s + " -o " + (dir_ / "prog.png").string() + " --tile 16");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("48/48 tiles"), std::string::npos) << r.err;  // 12 tiles x 4 passes
  int w1, h1, w2, h2;
  auto one = load_rgb8(dir_ / "one.png", &w1, &h1), prog = load_rgb8(dir_ / "prog.png", &w2, &h2);
  ASSERT_EQ(one.size(), prog.size());
  ASSERT_FALSE(one.empty());
  int worst = 0;
  for (size_t i = 0; i < one.size(); ++i) worst = std::max(worst, std::abs(int(one[i]) - int(prog[i])));
  EXPECT_LE(worst, 1);  // gamma is undone and redone between passes: rounding only
}

TEST_F(OfflineOutput, SequenceOfThreeFramesFromOneBuild) {
  std::string s = scene(
      "render: {width: 48, height: 32}\n"
      "camera:\n  path:\n    interpolation: catmull_rom\n    keys:\n"
      "      - {time: 0, position: [4, -4, 2], target: [0, 0, 0.5]}\n"
      "      - {time: 1, position: [0, -5, 1], target: [0, 0, 0.5]}\n"
      "      - {time: 2, position: [-4, -4, 2], target: [0, 0, 0.5]}\n"
      "scene:\n  union:\n    - plane: {}\n    - box: {}\n      translate: [0.3, 0, 0.5]\n");
  Result r = sdfc("render " + s + " --frames 0:2 --fps 1 -o " + (dir_ / "seq" / "f_%02d.png").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(kernel_builds(r.err), 1u) << r.err;  // one kernel build for all frames
  expect_three_different_frames(dir_ / "seq");
}

// Animated scene values: three frames, three different images, one build;
// frame 1 (time 1 s at --fps 1) matches the static scene with the values at
// time 1 written out.
TEST_F(OfflineOutput, AnimatedValuesRenderEveryFrameFromOneBuild) {
  const std::string head = "render: {width: 64, height: 40}\ncamera: {position: [0, -5, 1.5], target: [0, 0, 0.3]}\n";
  std::string s = scene(head +
      "scene:\n  union:\n    - plane: {}\n"
      "    - {sphere: {radius: \"0.4 + 0.1*time\"}, translate: [\"0.5*time - 0.5\", 0, 0.6]}\n"
      "    - {box: {size: [0.5, 0.5, 0.5]}, rotate: {axis: [0, 0, 1], degrees: \"30*time\"}, translate: [-1.2, 0, 0.3]}\n"
      "    - {mandelbulb: {power: \"7 + sin(time)\", iterations: 6}, scale: 0.5, translate: [1.3, 0, 0.6]}\n");
  Result r = sdfc("render " + s + " --frames 0:2 --fps 1 -o " + (dir_ / "seq" / "f_%02d.png").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(kernel_builds(r.err), 1u) << r.err;
  expect_three_different_frames(dir_ / "seq");
  // The same scene at time 1, written out (the bulb's power, 7 + sin(1), takes the trig
  // formula, so the bulb is left out of this comparison).
  std::string animated = scene(head +
      "scene:\n  union:\n    - plane: {}\n"
      "    - {sphere: {radius: \"0.4 + 0.1*time\"}, translate: [\"0.5*time - 0.5\", 0, 0.6]}\n"
      "    - {box: {size: [0.5, 0.5, 0.5]}, rotate: {axis: [0, 0, 1], degrees: \"30*time\"}, translate: [-1.2, 0, 0.3]}\n");
  ASSERT_EQ(sdfc("render " + animated + " --frames 1 --fps 1 -q -o " + (dir_ / "a_%d.png").string()).code, 0);
  std::string fixed = scene(head +
      "scene:\n  union:\n    - plane: {}\n"
      "    - {sphere: {radius: 0.5}, translate: [0, 0, 0.6]}\n"
      "    - {box: {size: [0.5, 0.5, 0.5]}, rotate: {axis: [0, 0, 1], degrees: 30}, translate: [-1.2, 0, 0.3]}\n");
  ASSERT_EQ(sdfc("render " + fixed + " -q -o " + (dir_ / "fixed.png").string()).code, 0);
  int w = 0, h = 0, w2, h2;
  auto a = load_rgb8(dir_ / "a_1.png", &w, &h), b = load_rgb8(dir_ / "fixed.png", &w2, &h2);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  long total = 0;
  int worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    int d = std::abs(int(a[i]) - int(b[i]));
    total += d;
    worst = std::max(worst, d);
  }
  // float rounding of the per-frame expressions and the wider (animated) march bounds only
  EXPECT_LE(worst, 8);
  EXPECT_LT(double(total) / double(a.size()), 0.5);
}

// Animated lights and fog: the frames differ although the geometry is static.
TEST_F(OfflineOutput, AnimatedLightsAndFog) {
  std::string s = scene("render: {width: 48, height: 32}\ncamera: {position: [0, -5, 2], target: [0, 0, 0.4]}\n"
                        "lights:\n  - point: {position: [\"2*sin(time)\", -2, 3], intensity: \"6 + 4*sin(time)\"}\n"
                        "  - ambient: {intensity: 0.2}\n"
                        "effects: {fog: {color: [0.5, 0.6, 0.7], density: \"0.1 + 0.08*sin(time)\"}}\n"
                        "scene: {union: [{plane: {}}, {sphere: {radius: 0.5}, translate: [0, 0, 0.5]}]}\n");
  Result r = sdfc("render " + s + " --frames 0:1 --fps 1 -o " + (dir_ / "l_%d.png").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(kernel_builds(r.err), 1u) << r.err;
  int w, h;
  auto a = load_rgb8(dir_ / "l_0.png", &w, &h), b = load_rgb8(dir_ / "l_1.png", &w, &h);
  ASSERT_FALSE(a.empty());
  EXPECT_NE(a, b);
}

// --aov iterations: the escape iteration of the fractal a pixel hits, 0 on
// other surfaces and misses.
TEST_F(OfflineOutput, IterationsAov) {
  std::string s = scene("render: {width: 64, height: 32}\ncamera: {position: [0, -4, 0], target: [0, 0, 0]}\n"
                        "materials: {bulb: {color: [0.9, 0.8, 0.7]}}\n"
                        "scene:\n  union:\n    - {mandelbulb: {power: 8, iterations: 9}, translate: [-1, 0, 0], material: bulb}\n"
                        "    - {sphere: {radius: 0.6}, translate: [1.2, 0, 0]}\n");
  Result r = sdfc("render " + s + " -q -o " + (dir_ / "img.png").string() + " --aov iterations,material");
  ASSERT_EQ(r.code, 0) << r.err;
  auto plane = [&](const char* aov) {
    std::string bytes = slurp(dir_ / (std::string("img.") + aov + ".pfm"));
    std::string header = "Pf\n64 32\n-1.0\n";
    EXPECT_EQ(bytes.substr(0, header.size()), header) << aov;
    std::vector<float> v(64 * 32, -99.0f);
    if (bytes.size() == header.size() + v.size() * sizeof(float)) std::memcpy(v.data(), bytes.data() + header.size(), v.size() * sizeof(float));
    return v;
  };
  std::vector<float> it = plane("iterations"), mat = plane("material");
  int bulb = 0, other = 0, below_max = 0;
  for (size_t i = 0; i < it.size(); ++i) {
    ASSERT_EQ(it[i], std::floor(it[i])) << i;  // a count
    if (mat[i] == 1.0f) {  // the bulb's material
      ++bulb;
      EXPECT_GE(it[i], 1.0f) << i;
      EXPECT_LE(it[i], 9.0f) << i;
      below_max += it[i] < 9.0f;
    } else {
      ++other;
      EXPECT_EQ(it[i], 0.0f) << i << " material " << mat[i];
    }
  }
  EXPECT_GT(bulb, 100);
  EXPECT_GT(other, 100);
  // The surface is where orbits start to escape: not every pixel runs the full count.
  EXPECT_GT(below_max, bulb / 10) << below_max << " of " << bulb;
}

// A PFM of `channels` planes as row-major top-to-bottom pixels (PFM rows run
// bottom-to-top); empty if the header or size is not as expected.
std::vector<float> read_pfm(const fs::path& p, int w, int h, int channels) {
  std::string bytes = slurp(p);
  std::string header = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1.0\n";
  const size_t n = size_t(w) * size_t(h) * size_t(channels);
  if (bytes.substr(0, header.size()) != header || bytes.size() != header.size() + n * sizeof(float)) return {};
  std::vector<float> file(n), v(n);
  std::memcpy(file.data(), bytes.data() + header.size(), n * sizeof(float));
  for (int y = 0; y < h; ++y)
    std::copy_n(file.begin() + long(size_t(h - 1 - y) * w * channels), size_t(w) * channels, v.begin() + long(size_t(y) * w * channels));
  return v;
}

// With several samples the AOVs are pixel averages: "hit" is the coverage.
// A sphere of radius 1 seen from 5 away is a disc of radius 1/sqrt(24) on the
// image plane; each pixel's coverage must match the disc's area fraction in
// that pixel (integrated on a fine grid here), fractional on the silhouette,
// and a render of one sample gives only 0 and 1. The progressive render
// (one pass per sample, averaged on the host) and the one-pass render
// (--repeat: the kernel averages) give the same AOVs.
TEST_F(OfflineOutput, SampledAovsArePixelAverages) {
  const int W = 24, H = 24;
  const std::string view = "camera: {position: [0, -5, 0], target: [0, 0, 0], fov: 45}\nscene: {sphere: {radius: 1}}\n";
  auto render = [&](const std::string& name, const std::string& extra, const std::string& opts) {
    std::string s = scene("render: {width: 24, height: 24, hit_epsilon: 0.01, max_steps: 4000" + extra + "}\n" + view);
    Result r = sdfc("render " + s + " -q -o " + (dir_ / (name + ".png")).string() + " --aov hit,depth,normal " + opts);
    EXPECT_EQ(r.code, 0) << r.err;
    return std::make_tuple(read_pfm(dir_ / (name + ".hit.pfm"), W, H, 1), read_pfm(dir_ / (name + ".depth.pfm"), W, H, 1),
                           read_pfm(dir_ / (name + ".normal.pfm"), W, H, 3));
  };
  auto [hit, depth, normal] = render("grid", ", samples: 256, sampling: grid", "");
  auto [hit1, depth1, normal1] = render("one", "", "");
  auto [hit_r, depth_r, normal_r] = render("once", ", samples: 256, sampling: grid", "--repeat 1");
  auto [hit_r2, depth_r2, normal_r2] = render("r2", ", samples: 64", "");  // the default R2 pattern
  ASSERT_FALSE(hit_r2.empty());
  ASSERT_FALSE(hit.empty());
  ASSERT_FALSE(hit1.empty());
  ASSERT_FALSE(hit_r.empty());
  ASSERT_FALSE(normal.empty());

  const double tan_half = std::tan(45.0 * M_PI / 360.0), rho2 = 1.0 / 24.0;
  int partial = 0;
  double worst = 0;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const int k = j * W + i, sub = 64;
      int inside = 0;
      for (int b = 0; b < sub; ++b)
        for (int a = 0; a < sub; ++a) {
          double x = (2.0 * (i + (a + 0.5) / sub) / W - 1.0) * tan_half, y = (1.0 - 2.0 * (j + (b + 0.5) / sub) / H) * tan_half;
          inside += x * x + y * y < rho2;
        }
      const double area = double(inside) / (sub * sub);
      worst = std::max(worst, std::fabs(hit[k] - area));
      EXPECT_NEAR(hit[k], area, 0.03) << "pixel " << i << ", " << j;
      EXPECT_NEAR(hit_r2[k], area, 0.1) << "R2, pixel " << i << ", " << j;
      if (hit[k] > 0.05 && hit[k] < 0.95) ++partial;
      EXPECT_TRUE(hit1[k] == 0.0f || hit1[k] == 1.0f) << hit1[k];
      EXPECT_EQ(hit1[k] > 0, depth1[k] >= 0);
      EXPECT_EQ(hit[k] > 0, depth[k] >= 0);
      if (hit[k] > 0) {
        // the mean over the samples that hit: between the nearest and farthest point of the sphere
        EXPECT_GE(depth[k], 4.0f - 1e-3f);
        EXPECT_LE(depth[k], 5.0f);
        const float* n = &normal[3 * k];
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0f, 1e-4f);  // normalised mean
      }
      EXPECT_NEAR(hit_r[k], hit[k], 1e-6) << "pixel " << i << ", " << j;
      EXPECT_NEAR(depth_r[k], depth[k], 1e-4 * std::max(1.0f, std::fabs(depth[k])));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(normal_r[3 * k + c], normal[3 * k + c], 1e-4);
    }
  EXPECT_GT(partial, 20);  // the silhouette crosses ~40 pixels
  std::cout << "coverage against the disc's area fraction: worst " << worst << ", " << partial << " partial pixels\n";
}

TEST_F(OfflineOutput, BadFrameOptionsAreUsageErrors) {
  std::string s = scene("render: {width: 16, height: 16}\nscene: {sphere: {}}\n");
  Result a = sdfc("render " + s + " --frames 5:2 -o " + (dir_ / "f_%d.png").string());
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.err.find("FIRST"), std::string::npos) << a.err;
  Result b = sdfc("render " + s + " --frames 0:3 -o " + (dir_ / "f.png").string());
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("%04d"), std::string::npos) << b.err;
  Result c = sdfc("render " + s + " --aov depth,iterationz -o " + (dir_ / "f.png").string());
  EXPECT_EQ(c.code, 2);
}

}  // namespace
