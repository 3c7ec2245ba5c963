// Region files: what is written is read back, sample for sample and in its
// place; unfinished or damaged files are refused, and never appear under
// their final name.
#include <gtest/gtest.h>

#include <sdfrt/errors.hpp>
#include <sdfrt/region_file.hpp>

#include <filesystem>
#include <fstream>

#include "shard.hpp"
#include "test_files.hpp"

namespace sdfrt {
namespace {

RegionHeader header() {
  RegionHeader h;
  h.image_width = 9, h.image_height = 7;
  h.x0 = 2, h.y0 = 1, h.x1 = 7, h.y1 = 5;  // 5 x 4
  h.bit_depth = 16;
  h.part = 1, h.parts = 3;
  h.fingerprint = region_fingerprint("scene");
  h.sections = {{"beauty", 3}, {"depth", 1}};
  return h;
}

// A band with plane k's sample at (x, y) = 1000 k + 10 y + x.
FloatImage band(int width, int y0, int rows) {
  FloatImage b(width, rows, {"r", "g", "b", "depth"});
  for (int k = 0; k < 4; ++k)
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < width; ++x) b.plane(k)[std::size_t(y * width + x)] = float(1000 * k + 10 * (y0 + y) + x);
  return b;
}

TEST(RegionFile, RoundTrip) {
  sdfc::test::TempDir dir;
  const std::string path = (dir.path() / "p.region").string();
  {
    RegionWriter w(path, header());
    auto beauty = w.section("beauty", {0, 1, 2});
    auto depth = w.section("depth", {3});
    // Bands of different heights; the sections are written interleaved.
    beauty->write_band(band(5, 0, 3));
    depth->write_band(band(5, 0, 1));
    depth->write_band(band(5, 1, 3));
    beauty->write_band(band(5, 3, 1));
    beauty->finish();
    depth->finish();
    EXPECT_FALSE(std::filesystem::exists(path));  // not before commit
    w.commit();
  }
  EXPECT_EQ(dir.file_names(), std::vector<std::string>{"p.region"});
  RegionReader r(path);
  EXPECT_EQ(r.header().image_width, 9);
  EXPECT_EQ(r.header().y1, 5);
  EXPECT_EQ(r.header().part, 1);
  EXPECT_EQ(r.header().parts, 3);
  EXPECT_EQ(r.header().bit_depth, 16);
  EXPECT_EQ(r.header().fingerprint, region_fingerprint("scene"));
  ASSERT_EQ(r.header().sections.size(), 2u);
  std::vector<float> rows(5 * 3 * 2);
  r.read_rows(0, 2, 2, rows.data());
  EXPECT_EQ(rows[0], 20.0f);        // r at (0, 2)
  EXPECT_EQ(rows[1], 1020.0f);      // g
  EXPECT_EQ(rows[3 * 4 + 2], 2024.0f);  // b at (4, 2)
  EXPECT_EQ(rows[15], 30.0f);       // r at (0, 3)
  std::vector<float> d(5);
  r.read_rows(1, 3, 1, d.data());
  EXPECT_EQ(d[4], 3034.0f);
  EXPECT_TRUE(sdfc::cli::output_complete(path));
}

TEST(RegionFile, UnfinishedWriterLeavesNothing) {
  sdfc::test::TempDir dir;
  const std::string path = (dir.path() / "p.region").string();
  {
    RegionWriter w(path, header());
    auto beauty = w.section("beauty", {0, 1, 2});
    beauty->write_band(band(5, 0, 4));
    EXPECT_THROW(w.commit(), IoError);  // depth was never written
  }
  EXPECT_TRUE(dir.file_names().empty());
}

TEST(RegionFile, DamagedFilesAreRefused) {
  sdfc::test::TempDir dir;
  const std::string path = (dir.path() / "p.region").string();
  {
    RegionWriter w(path, header());
    w.section("beauty", {0, 1, 2})->write_band(band(5, 0, 4));
    w.section("depth", {3})->write_band(band(5, 0, 4));
    w.commit();
  }
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 4);
  EXPECT_FALSE(sdfc::cli::output_complete(path));
  try {
    RegionReader r(path);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "P6\n3 3\n255\n";
  EXPECT_THROW(RegionReader{path}, IoError);
  EXPECT_THROW(RegionReader{(dir.path() / "missing.region").string()}, IoError);
}

TEST(RegionFile, InvalidHeadersAreRefused) {
  sdfc::test::TempDir dir;
  RegionHeader h = header();
  h.x1 = 10;  // past the image
  EXPECT_THROW(RegionWriter((dir.path() / "a.region").string(), h), std::invalid_argument);
  h = header();
  h.part = 3;  // of 3
  EXPECT_THROW(RegionWriter((dir.path() / "b.region").string(), h), std::invalid_argument);
  RegionWriter w((dir.path() / "c.region").string(), header());
  EXPECT_THROW(w.section("normal", {0, 1, 2}), std::invalid_argument);
  EXPECT_THROW(w.section("depth", {0, 1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace sdfrt
