#include <sdfrt/errors.hpp>
#include <sdfrt/image_io.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <limits>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sdfrt {
namespace {

using test::TempDir;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// 5x3 RGB + depth where pixel (x,y) has r = x/4, g = y/2, b = 0.5.
FloatImage sample_image() {
  FloatImage image(5, 3, {"r", "g", "b", "depth"});
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * 5 + x);
      image.data[i] = x / 4.0f;
      image.data[15 + i] = y / 2.0f;
      image.data[30 + i] = 0.5f;
      image.data[45 + i] = 10.0f * y + x;
    }
  }
  return image;
}

std::uint8_t code(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

TEST(ToRgb8, ClampsRoundsAndZeroesNonFinite) {
  FloatImage image(6, 1, {"r", "g", "b"});
  const float r[] = {0.0f, 1.0f, 0.5f, -1.0f, 2.0f, kNaN};
  std::copy(std::begin(r), std::end(r), image.data.begin());
  image.data[6 + 1] = kInf;
  image.data[12 + 2] = -kInf;
  long long nonfinite = 0;
  const auto rgb = to_rgb8(image, {0, 1, 2}, &nonfinite);
  ASSERT_EQ(rgb.size(), 18u);
  EXPECT_EQ(rgb[0], 0);
  EXPECT_EQ(rgb[3], 255);
  EXPECT_EQ(rgb[6], 128);
  EXPECT_EQ(rgb[9], 0);
  EXPECT_EQ(rgb[12], 255);
  EXPECT_EQ(rgb[15], 0);
  EXPECT_EQ(rgb[4], 0) << "+Inf becomes 0, not 255";
  EXPECT_EQ(rgb[8], 0);
  EXPECT_EQ(nonfinite, 3);
}

TEST(WritePng, ReadsBackWithTheSamePixels) {
  TempDir dir;
  const std::string path = (dir.path() / "out.png").string();
  const FloatImage image = sample_image();
  const WriteReport report = write_png(path, image);
  EXPECT_EQ(report.path, path);
  EXPECT_EQ(report.nonfinite_samples, 0);
  EXPECT_EQ(report.bytes, std::filesystem::file_size(path));

  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
  EXPECT_EQ(w, 5);
  EXPECT_EQ(h, 3);
  EXPECT_EQ(channels, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const stbi_uc* p = pixels + (y * 5 + x) * 3;
      EXPECT_EQ(p[0], code(image.at(0, x, y)));
      EXPECT_EQ(p[1], code(image.at(1, x, y)));
      EXPECT_EQ(p[2], 128);
    }
  }
  stbi_image_free(pixels);
  EXPECT_EQ(dir.file_names(), std::vector<std::string>{"out.png"}) << "no temp file left";

  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask) << "normal file permissions, not mkstemp's 0600";
}

TEST(WritePng, NanPixelsBecomeZeroAndAreCounted) {
  TempDir dir;
  const std::string path = (dir.path() / "nan.png").string();
  FloatImage image = sample_image();
  image.data[0] = kNaN;           // r of (0,0)
  image.data[15 + 7] = kNaN;      // g of (2,1)
  image.data[30 + 14] = kInf;     // b of (4,2)
  image.data[45] = kNaN;          // depth is not written to the PNG
  EXPECT_EQ(write_png(path, image).nonfinite_samples, 3);

  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(pixels[0], 0);
  EXPECT_EQ(pixels[(1 * 5 + 2) * 3 + 1], 0);
  EXPECT_EQ(pixels[(2 * 5 + 4) * 3 + 2], 0);
  stbi_image_free(pixels);
}

TEST(WritePng, PlaneSelectionAndBadPlaneIndex) {
  TempDir dir;
  const std::string path = (dir.path() / "bgr.png").string();
  write_png(path, sample_image(), {2, 1, 0});
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load(path.c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(pixels[4 * 3 + 0], 128);
  EXPECT_EQ(pixels[4 * 3 + 2], 255);
  stbi_image_free(pixels);
  EXPECT_THROW(write_png(path, sample_image(), {0, 1, 4}), std::invalid_argument);
  EXPECT_THROW(write_png(path, FloatImage{}), std::invalid_argument);
}

TEST(WritePng, ReplacesAnExistingFile) {
  TempDir dir;
  const auto path = dir.path() / "again.png";
  std::ofstream(path) << "old contents";
  write_png(path.string(), sample_image());
  EXPECT_EQ(test::read_text_file(path).substr(1, 3), "PNG");
}

TEST(WriteErrors, MissingDirectoryThrowsIoErrorNamingPath) {
  TempDir dir;
  const std::string path = (dir.path() / "missing" / "out.png").string();
  try {
    write_png(path, sample_image());
    FAIL() << "expected IoError";
  } catch (const IoError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(e.errno_value(), ENOENT);
  }
  EXPECT_TRUE(dir.file_names().empty());
}

TEST(WriteErrors, ReadOnlyDirectoryThrowsIoErrorAndLeavesNothing) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  TempDir dir;
  const auto locked = dir.path() / "locked";
  std::filesystem::create_directory(locked);
  std::filesystem::permissions(locked, std::filesystem::perms::owner_read |
                                           std::filesystem::perms::owner_exec);
  EXPECT_THROW(write_png((locked / "out.png").string(), sample_image()), IoError);
  std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  EXPECT_TRUE(std::filesystem::is_empty(locked));
}

// RLIMIT_FSIZE makes write() fail with EFBIG part-way, like a full disk.
TEST(WriteErrors, FailedWriteRemovesTempFileAndKeepsOldImage) {
  TempDir dir;
  const auto path = dir.path() / "big.pfm";
  std::ofstream(path) << "previous image";
  FloatImage big(512, 512, {"depth"});

  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old_limit;
  small.rlim_cur = 64 * 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  bool threw = false;
  try {
    write_pfm(path.string(), big, 0);
  } catch (const IoError& e) {
    threw = true;
    EXPECT_EQ(e.errno_value(), EFBIG) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);

  EXPECT_TRUE(threw);
  EXPECT_EQ(dir.file_names(), std::vector<std::string>{"big.pfm"});
  EXPECT_EQ(test::read_text_file(path), "previous image");
}

TEST(WritePfm, SingleChannelHeaderSizeAndRowOrder) {
  TempDir dir;
  const auto path = dir.path() / "depth.pfm";
  FloatImage image = sample_image();
  image.data[45 + 14] = kNaN;  // depth of (4,2): bottom-right
  const WriteReport report = write_pfm(path.string(), image, 3);
  EXPECT_EQ(report.nonfinite_samples, 1);

  const std::string bytes = test::read_text_file(path);
  const std::string header = "Pf\n5 3\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 5 * 3 * sizeof(float));
  EXPECT_EQ(report.bytes, bytes.size());
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  std::vector<float> samples(15);
  std::memcpy(samples.data(), bytes.data() + header.size(), 15 * sizeof(float));
  // First stored row is the bottom image row (y = 2).
  EXPECT_EQ(samples[0], 20.0f);
  EXPECT_EQ(samples[3], 23.0f);
  EXPECT_EQ(samples[4], 0.0f) << "NaN written as 0";
  EXPECT_EQ(samples[10], 0.0f);  // top-left (0,0)
  EXPECT_EQ(samples[14], 4.0f);
}

TEST(WritePfm, RgbHeaderSizeAndInterleaving) {
  TempDir dir;
  const auto path = dir.path() / "color.pfm";
  const FloatImage image = sample_image();
  write_pfm_rgb(path.string(), image);
  const std::string bytes = test::read_text_file(path);
  const std::string header = "PF\n5 3\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 5 * 3 * 3 * sizeof(float));
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  float first_pixel[3];
  std::memcpy(first_pixel, bytes.data() + header.size() + 3 * sizeof(float), sizeof(first_pixel));
  // Second pixel of the bottom row: (1, 2).
  EXPECT_EQ(first_pixel[0], image.at(0, 1, 2));
  EXPECT_EQ(first_pixel[1], image.at(1, 1, 2));
  EXPECT_EQ(first_pixel[2], image.at(2, 1, 2));
  EXPECT_THROW(write_pfm(path.string(), image, 9), std::invalid_argument);
}

}  // namespace
}  // namespace sdfrt
