// Shard arithmetic: every frame in exactly one task, in order, balanced;
// strips that tile the image; the completeness checks a resuming task uses.
#include <gtest/gtest.h>

#include <sdfrt/image_io.hpp>
#include <sdfrt/stream_writers.hpp>

#include <filesystem>
#include <fstream>
#include <numeric>

#include "shard.hpp"
#include "test_files.hpp"

namespace sdfc::cli {
namespace {

std::vector<int> range(int first, int last) {
  std::vector<int> v(std::size_t(last - first + 1));
  std::iota(v.begin(), v.end(), first);
  return v;
}

TEST(Shard, ParsesTaskOverCount) {
  EXPECT_EQ(parse_shard("0/4").index, 0);
  EXPECT_EQ(parse_shard("3/4").index, 3);
  EXPECT_EQ(parse_shard("3/4").count, 4);
  for (const char* bad : {"4/4", "1/0", "-1/4", "1", "1/", "a/b", "1/4/5", ""})
    EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
  try {
    parse_shard("4/4");
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0 to 3"), std::string::npos) << e.what();
  }
}

TEST(Shard, ModesAndNearMisses) {
  EXPECT_EQ(parse_shard_mode("contiguous"), ShardMode::Contiguous);
  EXPECT_EQ(parse_shard_mode("strided"), ShardMode::Strided);
  try {
    parse_shard_mode("stride");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'strided'"), std::string::npos) << e.what();
  }
}

// For many sizes: the tasks' shares are disjoint, cover every item once,
// keep the order, and differ in size by at most one.
TEST(Shard, EveryItemInExactlyOneTask) {
  for (ShardMode mode : {ShardMode::Contiguous, ShardMode::Strided})
    for (int n : {1, 2, 7, 8, 9, 240})
      for (int tasks : {1, 2, 3, 4, 7, 100}) {
        const std::vector<int> items = range(10, 10 + n - 1);
        std::vector<int> seen;
        std::size_t smallest = items.size(), largest = 0;
        for (int k = 0; k < tasks; ++k) {
          std::vector<int> mine = shard_items(items, {k, tasks}, mode);
          EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
          smallest = std::min(smallest, mine.size()), largest = std::max(largest, mine.size());
          seen.insert(seen.end(), mine.begin(), mine.end());
        }
        std::sort(seen.begin(), seen.end());
        EXPECT_EQ(seen, items) << n << " items, " << tasks << " tasks";
        EXPECT_LE(largest - smallest, 1u) << n << " items, " << tasks << " tasks";
      }
}

TEST(Shard, ContiguousRunsAndStridedSteps) {
  EXPECT_EQ(shard_items(range(0, 7), {1, 4}, ShardMode::Contiguous), (std::vector<int>{2, 3}));
  EXPECT_EQ(shard_items(range(0, 7), {1, 4}, ShardMode::Strided), (std::vector<int>{1, 5}));
  EXPECT_EQ(shard_items(range(0, 2), {3, 4}, ShardMode::Contiguous), (std::vector<int>{2}));
  EXPECT_TRUE(shard_items(range(0, 2), {0, 4}, ShardMode::Contiguous).empty());
}

TEST(Strips, TileTheImage) {
  for (int h : {1, 7, 30, 50, 16384})
    for (int parts : {1, 2, 3, 4, 7}) {
      if (parts > h) {
        EXPECT_THROW(strip_region(10, h, 0, parts), std::invalid_argument);
        continue;
      }
      int y = 0;
      for (int k = 0; k < parts; ++k) {
        Rect r = strip_region(10, h, k, parts);
        EXPECT_EQ(r.y0, y);
        EXPECT_EQ(r.x0, 0);
        EXPECT_EQ(r.x1, 10);
        EXPECT_GE(r.height(), h / parts);
        EXPECT_LE(r.height(), h / parts + 1);
        y = r.y1;
      }
      EXPECT_EQ(y, h);
    }
}

TEST(Region, ParsesCornersInsideTheImage) {
  Rect r = parse_region("1, 2,30,40", 64, 48);
  EXPECT_EQ(r.x0, 1);
  EXPECT_EQ(r.y0, 2);
  EXPECT_EQ(r.x1, 30);
  EXPECT_EQ(r.y1, 40);
  for (const char* bad : {"0,0,65,48", "0,0,64,49", "5,0,5,10", "0,9,10,3", "1,2,3", "a,b,c,d", "-1,0,4,4"})
    EXPECT_THROW(parse_region(bad, 64, 48), std::invalid_argument) << bad;
}

// A resuming task trusts a frame only when its file is whole.
TEST(OutputComplete, WholeFilesOnly) {
  test::TempDir dir;
  const std::string png = (dir.path() / "f.png").string(), pfm = (dir.path() / "f.depth.pfm").string();
  EXPECT_FALSE(output_complete(png));
  sdfrt::FloatImage img(8, 4, {"r", "g", "b", "depth"});
  sdfrt::write_png(png, img);
  sdfrt::write_pfm(pfm, img, 3);
  EXPECT_TRUE(output_complete(png));
  EXPECT_TRUE(output_complete(pfm));
  for (const std::string& p : {png, pfm}) {
    const auto size = std::filesystem::file_size(p);
    std::filesystem::resize_file(p, size - 1);
    EXPECT_FALSE(output_complete(p)) << p;
  }
  std::ofstream(png, std::ios::trunc).close();
  EXPECT_FALSE(output_complete(png));  // empty
}

}  // namespace
}  // namespace sdfc::cli
