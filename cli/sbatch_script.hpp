#pragma once
// The text of the Slurm job scripts `sdfc farm slurm` writes: a job array
// whose tasks each render their share (--shard $SLURM_ARRAY_TASK_ID/
// $SLURM_ARRAY_TASK_COUNT), for a still a merge job, and a submit script
// that queues them (the merge only after every part succeeded).
#include <string>
#include <vector>

namespace sdfc::cli {

struct FarmJob {
  std::string sdfc;         // absolute path of the sdfc binary the tasks run
  std::string workdir;      // where the tasks start (relative paths resolve here)
  std::string scene;
  std::vector<std::string> render_args;  // passed through: --set, --aov, --bit-depth, ...
  std::string frames;       // animation: --frames a:b ("" for a still)
  int still_width = 0, still_height = 0, parts = 0;  // a still
  int tasks = 1;
  std::string partition, time, mem;  // "" leaves Slurm's default
  int cpus_per_task = 0;             // 0: Slurm's default
  bool exclusive = false;            // a whole node per task
  std::string output;       // frames: the pattern; still: the final PNG
  std::string parts_pattern;  // still: where the region files go (part_%03d.region)
  std::vector<std::string> part_files;  // still: that pattern for each part, in order
  std::string cache_dir;    // SDFC_CACHE_DIR for every task: shared, so the kernel is built once
  std::string log_dir;
  std::string name;         // job name
};

// Single-quoted for /bin/sh ('it'\''s').
std::string shell_quote(const std::string& s);

// The job array script (sbatch FILE).
std::string array_script(const FarmJob& job);
// A still's merge job script (sbatch --dependency=afterok:ID FILE).
std::string merge_script(const FarmJob& job);
// Submits the array and, for a still, the merge job after it; prints the
// job ids. `array_file`/`merge_file` are the scripts' paths.
std::string submit_script(const FarmJob& job, const std::string& array_file, const std::string& merge_file);

}  // namespace sdfc::cli
