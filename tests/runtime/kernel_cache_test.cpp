#include <sdfrt/program.hpp>
#include <sdfrt/renderer.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

namespace sdfrt {
namespace {

using test::ScopedEnv;
using test::same_bits;
using test::TempDir;

FloatImage render_small(Renderer& renderer) {
  RenderOptions options;
  options.tile_width = 16;
  options.tile_height = 16;
  return renderer.render({0.25f}, 40, 20, options);
}

TEST(KernelCache, SecondBuildIsAHitWithIdenticalOutput) {
  TempDir dir;
  ScopedEnv cache_dir("SDFC_CACHE_DIR", dir.path().string());
  ScopedEnv cache_on("SDFC_KERNEL_CACHE", std::nullopt);

  Renderer first(test::test_device(), test::gradient_spec(8));
  EXPECT_FALSE(first.build_stats().cache_hit);
  ASSERT_EQ(dir.file_names().size(), 1u);
  EXPECT_EQ(first.build_stats().cache_path, (dir.path() / dir.file_names()[0]).string());
  EXPECT_GT(first.build_stats().build_ms, 0.0);

  Renderer second(test::test_device(), test::gradient_spec(8));
  EXPECT_TRUE(second.build_stats().cache_hit) << second.build_stats().cache_note;
  EXPECT_TRUE(same_bits(render_small(first), render_small(second)));
  EXPECT_EQ(dir.file_names().size(), 1u) << "no temp files left behind";
}

TEST(KernelCache, KeyCoversSourceAndOptions) {
  TempDir dir;
  ScopedEnv cache_dir("SDFC_CACHE_DIR", dir.path().string());
  const std::string source = test::gradient_spec(1).source;
  BuildStats stats;
  build_program(test::test_device(), source, "", &stats);
  build_program(test::test_device(), source, "-cl-fast-relaxed-math", &stats);
  EXPECT_FALSE(stats.cache_hit);
  build_program(test::test_device(), source + "\n// edited\n", "", &stats);
  EXPECT_FALSE(stats.cache_hit);
  EXPECT_EQ(dir.file_names().size(), 3u);
  build_program(test::test_device(), source, "-cl-fast-relaxed-math", &stats);
  EXPECT_TRUE(stats.cache_hit);
}

TEST(KernelCache, CorruptOrTruncatedEntryFallsBackToSourceBuild) {
  TempDir dir;
  ScopedEnv cache_dir("SDFC_CACHE_DIR", dir.path().string());
  Renderer original(test::test_device(), test::gradient_spec(1));
  const auto entry = dir.path() / dir.file_names().at(0);
  const std::string good = test::read_text_file(entry);
  ASSERT_GT(good.size(), 64u);

  const std::string damaged[] = {
      "garbage that is not a kernel binary",
      good.substr(0, good.size() / 2),                              // truncated
      good.substr(0, 40) + std::string(good.size() - 40, '\x5a'),   // payload overwritten
  };
  for (const std::string& bytes : damaged) {
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
    Renderer rebuilt(test::test_device(), test::gradient_spec(1));
    EXPECT_FALSE(rebuilt.build_stats().cache_hit);
    EXPECT_TRUE(same_bits(render_small(original), render_small(rebuilt)));
    // Rewritten with a valid entry (binaries need not be byte-identical).
    const std::string rewritten = test::read_text_file(entry);
    EXPECT_NE(rewritten, bytes);
    EXPECT_EQ(rewritten.substr(0, 8), "SDFCKBIN");
  }
  Renderer cached(test::test_device(), test::gradient_spec(1));
  EXPECT_TRUE(cached.build_stats().cache_hit);
}

TEST(KernelCache, DisabledByEnvironment) {
  TempDir dir;
  ScopedEnv cache_dir("SDFC_CACHE_DIR", dir.path().string());
  ScopedEnv cache_off("SDFC_KERNEL_CACHE", "0");
  EXPECT_FALSE(kernel_cache_enabled());
  BuildStats stats;
  build_program(test::test_device(), test::gradient_spec(1).source, "", &stats);
  build_program(test::test_device(), test::gradient_spec(1).source, "", &stats);
  EXPECT_FALSE(stats.cache_hit);
  EXPECT_TRUE(stats.cache_path.empty());
  EXPECT_TRUE(dir.file_names().empty());
}

TEST(KernelCache, UnwritableDirectoryDoesNotFailTheBuild) {
  TempDir dir;
  const auto blocker = dir.path() / "not-a-directory";
  std::ofstream(blocker) << "x";
  ScopedEnv cache_dir("SDFC_CACHE_DIR", (blocker / "kernels").string());
  BuildStats stats;
  EXPECT_NO_THROW(build_program(test::test_device(), test::gradient_spec(1).source, "", &stats));
  EXPECT_FALSE(stats.cache_hit);
  EXPECT_FALSE(stats.cache_note.empty());
}

TEST(KernelCache, DirectoryFollowsEnvironment) {
  {
    ScopedEnv a("SDFC_CACHE_DIR", "/x/sdfc-cache");
    EXPECT_EQ(kernel_cache_dir(), std::filesystem::path("/x/sdfc-cache"));
  }
  ScopedEnv no_dir("SDFC_CACHE_DIR", std::nullopt);
  {
    ScopedEnv xdg("XDG_CACHE_HOME", "/x/xdg");
    EXPECT_EQ(kernel_cache_dir(), std::filesystem::path("/x/xdg/sdfc/kernels"));
  }
  ScopedEnv no_xdg("XDG_CACHE_HOME", std::nullopt);
  ScopedEnv home("HOME", "/x/home");
  EXPECT_EQ(kernel_cache_dir(), std::filesystem::path("/x/home/.cache/sdfc/kernels"));
}

}  // namespace
}  // namespace sdfrt
