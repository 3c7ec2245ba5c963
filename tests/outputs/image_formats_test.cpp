// Images as a compositor reads them: PNG alpha against the hit coverage, EXR
// channels against the PFM AOVs of the same render, JPEG through a decoder.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include <cmath>
#include <cstring>
#include <map>
#include <sdfrt/image_read.hpp>
#include <string>
#include <vector>

#include "run_sdfc.hpp"

namespace {

using sdfc::test::RunResult;
using sdfc::test::ScratchDir;

constexpr int W = 64, H = 48;
// A sphere that covers part of the frame, with 4 samples so its edge has
// fractional coverage.
const char* kScene =
    "render: {width: 64, height: 48, samples: 4}\n"
    "camera: {position: [0, -4, 0.5], target: [0.4, 0, 0]}\n"
    "scene: {union: [{sphere: {radius: 1}}, {translate: [1.4, 0, 0], box: {size: [0.3, 0.3, 0.3]}}]}\n";

// Channel name -> float pixels, top row first.
std::map<std::string, std::vector<float>> read_exr(const std::string& path, int* w, int* h,
                                                   std::map<std::string, Imf::PixelType>* types = nullptr) {
  Imf::InputFile in(path.c_str());
  const auto dw = in.header().dataWindow();
  *w = dw.max.x - dw.min.x + 1, *h = dw.max.y - dw.min.y + 1;
  std::map<std::string, std::vector<float>> out;
  Imf::FrameBuffer fb;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
    auto& v = out[it.name()];
    v.resize(std::size_t(*w) * std::size_t(*h));
    if (types) (*types)[it.name()] = it.channel().type;
    fb.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), sizeof(float), sizeof(float) * *w));
  }
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  return out;
}

std::vector<unsigned char> load_png(const std::string& path, int channels, int* w, int* h) {
  int n = 0;
  unsigned char* p = stbi_load(path.c_str(), w, h, &n, channels);
  if (!p) return {};
  std::vector<unsigned char> v(p, p + std::size_t(*w) * std::size_t(*h) * std::size_t(channels));
  stbi_image_free(p);
  return v;
}

TEST(ImageFormats, PngAlphaIsTheHitCoverageAndLeavesTheBackgroundOut) {
  ScratchDir dir;
  const std::string s = dir.write("s.yaml", kScene);
  RunResult r = sdfc::test::run_sdfc("render " + s + " --alpha --aov hit -q -o " + dir.file("a.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  r = sdfc::test::run_sdfc("render " + s + " -q -o " + dir.file("plain.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  int w = 0, h = 0;
  auto rgba = load_png(dir.file("a.png"), 4, &w, &h);
  auto plain = load_png(dir.file("plain.png"), 3, &w, &h);
  ASSERT_EQ(rgba.size(), std::size_t(W * H * 4));
  sdfrt::FloatImage hit = sdfrt::read_pfm(dir.file("a.hit.pfm"), "hit");
  int partial = 0, opaque = 0, clear = 0;
  for (int i = 0; i < W * H; ++i) {
    const float k = hit.plane(0)[std::size_t(i)];
    ASSERT_NEAR(rgba[std::size_t(i) * 4 + 3], k * 255.0f, 0.51f) << "pixel " << i;
    if (k == 0.0f) {
      ++clear;  // no background in the colour
      for (int c = 0; c < 3; ++c) EXPECT_EQ(rgba[std::size_t(i) * 4 + c], 0) << "pixel " << i;
    } else if (k == 1.0f) {
      ++opaque;  // fully covered: the colour of the render without alpha
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rgba[std::size_t(i) * 4 + c], plain[std::size_t(i) * 3 + c], 1) << "pixel " << i;
    } else {
      ++partial;
    }
  }
  EXPECT_GT(clear, 100);
  EXPECT_GT(opaque, 100);
  EXPECT_GT(partial, 10) << "the edge has fractional coverage";
}

TEST(ImageFormats, ExrChannelsEqualThePfmAovsOfTheSameRender) {
  ScratchDir dir;
  const std::string s = dir.write("s.yaml", kScene);
  const std::string aovs = " --aov depth,normal,steps,iterations,material,hit -q";
  ASSERT_EQ(sdfc::test::run_sdfc("render " + s + aovs + " -o " + dir.file("p.png")).code, 0);
  // in bands of 16 rows (--tile 16): every band lands on its own rows
  RunResult r = sdfc::test::run_sdfc("render " + s + aovs + " --bit-depth 32 --tile 16 -o " + dir.file("f.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, dir.file("f.exr") + "\n") << "one file, no PFMs beside it";
  r = sdfc::test::run_sdfc("render " + s + aovs + " --alpha -o " + dir.file("h.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  int w = 0, h = 0;
  std::map<std::string, Imf::PixelType> ft, ht;
  auto f = read_exr(dir.file("f.exr"), &w, &h, &ft);
  ASSERT_EQ(w, W);
  ASSERT_EQ(h, H);
  auto hx = read_exr(dir.file("h.exr"), &w, &h, &ht);
  const std::map<std::string, std::pair<std::string, std::string>> from_pfm = {
      {"Z", {"depth", "depth"}},  {"N.X", {"normal", "normal.x"}}, {"N.Y", {"normal", "normal.y"}},
      {"N.Z", {"normal", "normal.z"}}, {"steps", {"steps", "steps"}},  {"iterations", {"iterations", "iterations"}},
      {"material", {"material", "material"}}, {"hit", {"hit", "hit"}}};
  for (const auto& [channel, pfm] : from_pfm) {
    ASSERT_TRUE(f.count(channel)) << channel;
    EXPECT_EQ(ft[channel], Imf::FLOAT) << channel;
    sdfrt::FloatImage img = sdfrt::read_pfm(dir.file("p." + pfm.first + ".pfm"), pfm.first);
    auto plane = img.plane(img.plane_index(pfm.second));
    for (std::size_t i = 0; i < plane.size(); ++i) {
      ASSERT_EQ(std::memcmp(&f[channel][i], &plane[i], 4), 0) << channel << " pixel " << i << ": " << f[channel][i]
                                                               << " vs " << plane[i];
      ASSERT_EQ(hx[channel][i], plane[i]) << "AOVs stay float in a half EXR: " << channel;
    }
  }
  // The beauty is linear: encoded with the gamma it is the PNG (the default
  // tone curve clamps to [0, 1]); half holds it to half precision.
  int pw = 0, ph = 0;
  auto png = load_png(dir.file("p.png"), 3, &pw, &ph);
  EXPECT_EQ(ht["R"], Imf::HALF);
  EXPECT_EQ(ft["R"], Imf::FLOAT);
  EXPECT_TRUE(hx.count("A") && !f.count("A")) << "alpha only with --alpha";
  const char* rgb[3] = {"R", "G", "B"};
  double above_one = 0;
  for (std::size_t i = 0; i < std::size_t(W * H); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float lin = f[rgb[c]][i];
      above_one = std::max<double>(above_one, lin);
      const float display = std::pow(std::clamp(lin, 0.0f, 1.0f), 1.0f / 2.2f) * 255.0f;
      ASSERT_NEAR(display, png[i * 3 + c], 1.01f) << rgb[c] << " pixel " << i;
    }
    // premultiplied: the colour of a pixel no sample hits is 0
    if (hx["A"][i] == 0.0f) {
      EXPECT_EQ(hx["R"][i] + hx["G"][i] + hx["B"][i], 0.0f) << i;
    } else if (hx["A"][i] == 1.0f) {
      EXPECT_NEAR(hx["G"][i], f["G"][i], 2e-3 * std::abs(f["G"][i]) + 1e-4) << i;
    }
  }
}

TEST(ImageFormats, JpegDecodesCloseToThePng) {
  ScratchDir dir;
  const std::string s = dir.write("s.yaml", kScene);
  ASSERT_EQ(sdfc::test::run_sdfc("render " + s + " -q -o " + dir.file("p.png")).code, 0);
  RunResult r = sdfc::test::run_sdfc("render " + s + " -q --quality 95 -o " + dir.file("j.jpeg"));
  ASSERT_EQ(r.code, 0) << r.err;
  int w = 0, h = 0;
  auto png = load_png(dir.file("p.png"), 3, &w, &h);
  auto jpg = load_png(dir.file("j.jpeg"), 3, &w, &h);  // stb reads JPEG too
  ASSERT_EQ(jpg.size(), png.size());
  double se = 0;
  for (std::size_t i = 0; i < png.size(); ++i) se += (double(png[i]) - jpg[i]) * (double(png[i]) - jpg[i]);
  const double psnr = 10 * std::log10(255.0 * 255.0 / std::max(se / double(png.size()), 1e-12));
  EXPECT_GT(psnr, 30.0);
  FILE* f = std::fopen(dir.file("j.jpeg").c_str(), "rb");
  ASSERT_TRUE(f);
  unsigned char magic[2] = {};
  EXPECT_EQ(std::fread(magic, 1, 2, f), 2u);
  std::fclose(f);
  EXPECT_EQ(magic[0], 0xFF);
  EXPECT_EQ(magic[1], 0xD8) << "JPEG data, not a PNG under that name";
}

// The path integrator's AOVs for denoisers (OIDN takes colour, albedo and
// normal): an EXR with --aov albedo,normal holds the layers albedo.R/G/B
// and N.X/N.Y/N.Z, the first hit's colour (1 on glass, 0 where nothing is
// hit) and its normal, averaged over the progressive passes.
TEST(ImageFormats, PathAlbedoAndNormalLayersForDenoisers) {
  ScratchDir dir;
  const std::string s = dir.write("p.yaml",
                                  "render: {width: 48, height: 24, samples: 8, integrator: path}\n"
                                  "camera: {position: [0, -6, 0], target: [0, 0, 0], fov: 40}\n"
                                  "materials: {paint: {color: [0.2, 0.4, 0.6], roughness: 0.3}, clear: {glass: {ior: 1.5}}}\n"
                                  "scene: {union: [{translate: [-1.2, 0, 0], sphere: {radius: 1}, material: paint},\n"
                                  "                {translate: [1.2, 0, 0], sphere: {radius: 1}, material: clear}]}\n");
  RunResult r = sdfc::test::run_sdfc("render " + s + " -q --aov albedo,normal -o " + dir.file("p.exr"));
  ASSERT_EQ(r.code, 0) << r.err;
  int w = 0, h = 0;
  auto c = read_exr(dir.file("p.exr"), &w, &h);
  ASSERT_EQ(w, 48);
  for (const char* name : {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z"})
    ASSERT_TRUE(c.count(name)) << name;
  // the pixel the left ball's centre is seen in, the right one's, a corner
  const std::size_t paint = 12 * 48 + 17, clear = 12 * 48 + 30, corner = 0;
  EXPECT_NEAR(c["albedo.R"][paint], 0.2, 2e-3);
  EXPECT_NEAR(c["albedo.G"][paint], 0.4, 2e-3);
  EXPECT_NEAR(c["albedo.B"][paint], 0.6, 2e-3);
  for (const char* ch : {"albedo.R", "albedo.G", "albedo.B"}) {
    EXPECT_NEAR(c[ch][clear], 1.0, 1e-3) << ch;
    EXPECT_EQ(c[ch][corner], 0.0f) << ch;
  }
  EXPECT_LT(c["N.Y"][paint], -0.95);  // it faces the camera
  EXPECT_LT(c["N.Y"][clear], -0.95);
  // the direct integrator has no albedo to give: a usage error
  r = sdfc::test::run_sdfc("render " + s + " -q --set render.integrator=direct --aov albedo -o " + dir.file("d.exr"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("path integrator"), std::string::npos) << r.err;
}

}  // namespace
