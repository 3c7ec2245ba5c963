// The job scripts: an array of the right size whose tasks pass their share
// to sdfc render, a merge that waits for every part, quoting that survives
// odd names, and the kernel cache on the shared path.
#include <gtest/gtest.h>

#include "sbatch_script.hpp"

namespace sdfc::cli {
namespace {

FarmJob still_job() {
  FarmJob j;
  j.sdfc = "/opt/sdfc/bin/sdfc";
  j.workdir = "/shared/proj";
  j.scene = "/shared/proj/it's.yaml";
  j.render_args = {"--set", "render.samples=16"};
  j.still_width = 640, j.still_height = 480, j.parts = 3, j.tasks = 3;
  j.output = "/shared/proj/out/print.png";
  j.parts_pattern = "/shared/proj/out/print.parts/part_%03d.region";
  j.part_files = {"/p/part_000.region", "/p/part_001.region", "/p/part_002.region"};
  j.cache_dir = "/shared/cache";
  j.log_dir = "/shared/proj/out/print.logs";
  j.name = "sdfc-print";
  j.partition = "render";
  j.time = "01:00:00";
  j.mem = "4G";
  j.cpus_per_task = 8;
  return j;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SbatchScript, StillArrayAndMerge) {
  const FarmJob j = still_job();
  const std::string a = array_script(j);
  EXPECT_EQ(a.rfind("#!/bin/bash\n", 0), 0u);
  EXPECT_TRUE(has(a, "#SBATCH --array=0-2\n")) << a;
  EXPECT_TRUE(has(a, "#SBATCH --partition=render\n"));
  EXPECT_TRUE(has(a, "#SBATCH --time=01:00:00\n"));
  EXPECT_TRUE(has(a, "#SBATCH --mem=4G\n"));
  EXPECT_TRUE(has(a, "#SBATCH --cpus-per-task=8\n"));
  EXPECT_FALSE(has(a, "--exclusive"));
  EXPECT_TRUE(has(a, "#SBATCH --requeue\n"));
  EXPECT_TRUE(has(a, "--shard \"$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT\"")) << a;
  EXPECT_TRUE(has(a, "--width 640 --height 480 --parts 3")) << a;
  EXPECT_TRUE(has(a, "'/shared/proj/it'\\''s.yaml'")) << a;
  EXPECT_TRUE(has(a, "'--set' 'render.samples=16'")) << a;
  EXPECT_TRUE(has(a, "SDFC_CACHE_DIR=\"${SDFC_CACHE_DIR:-/shared/cache}\"")) << a;
  const std::string m = merge_script(j);
  EXPECT_TRUE(has(m, "merge '/p/part_000.region' '/p/part_001.region' '/p/part_002.region' -o '/shared/proj/out/print.png'"))
      << m;
  const std::string s = submit_script(j, "/x/a.sbatch", "/x/m.sbatch");
  EXPECT_TRUE(has(s, "--dependency=afterok:\"$array\" --kill-on-invalid-dep=yes '/x/m.sbatch'")) << s;
}

TEST(SbatchScript, AnimationHasNoMerge) {
  FarmJob j = still_job();
  j.parts = 0, j.part_files.clear();
  j.frames = "0:239";
  j.tasks = 100;
  j.output = "/shared/out/f_%04d.png";
  const std::string a = array_script(j);
  EXPECT_TRUE(has(a, "#SBATCH --array=0-99\n"));
  EXPECT_TRUE(has(a, "--frames '0:239' --shard")) << a;
  EXPECT_TRUE(has(a, "-o '/shared/out/f_%04d.png'")) << a;
  EXPECT_FALSE(has(a, "--parts"));
  EXPECT_FALSE(has(submit_script(j, "/x/a.sbatch", ""), "dependency"));
}

TEST(SbatchScript, ShellQuote) {
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
}

}  // namespace
}  // namespace sdfc::cli
