#include "sbatch_script.hpp"

#include <fmt/format.h>


namespace sdfc::cli {
namespace {

std::string header(const FarmJob& job, const std::string& name, const std::string& log) {
  std::string s = "#!/bin/bash\n";
  s += fmt::format("#SBATCH --job-name={}\n", name);
  s += fmt::format("#SBATCH --chdir={}\n", job.workdir);
  s += fmt::format("#SBATCH --output={}/{}\n", job.log_dir, log);
  if (!job.partition.empty()) s += fmt::format("#SBATCH --partition={}\n", job.partition);
  if (!job.time.empty()) s += fmt::format("#SBATCH --time={}\n", job.time);
  if (!job.mem.empty()) s += fmt::format("#SBATCH --mem={}\n", job.mem);
  if (job.cpus_per_task > 0) s += fmt::format("#SBATCH --cpus-per-task={}\n", job.cpus_per_task);
  if (job.exclusive) s += "#SBATCH --exclusive\n";
  return s;
}

std::string render_command(const FarmJob& job) {
  std::string cmd = fmt::format("{} render {}", shell_quote(job.sdfc), shell_quote(job.scene));
  for (const auto& a : job.render_args) cmd += " " + shell_quote(a);
  if (job.parts > 0)
    cmd += fmt::format(" --width {} --height {} --parts {}", job.still_width, job.still_height, job.parts);
  else
    cmd += " --frames " + shell_quote(job.frames);
  cmd += " --shard \"$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT\"";
  cmd += " -o " + shell_quote(job.parts > 0 ? job.parts_pattern : job.output);
  return cmd;
}

std::string cache_line(const FarmJob& job) {
  return fmt::format(
      "# The kernel binary cache on shared storage: the first task builds the kernel, every other task\n"
      "# (on any node with the same OpenCL device and driver) loads it. Set SDFC_CACHE_DIR before\n"
      "# submitting to put it elsewhere.\n"
      "export SDFC_CACHE_DIR=\"${{SDFC_CACHE_DIR:-{}}}\"\n",
      job.cache_dir);
}

}  // namespace

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string array_script(const FarmJob& job) {
  std::string s = header(job, job.name, "%x-%A_%a.log");
  s += fmt::format("#SBATCH --array=0-{}\n", job.tasks - 1);
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --requeue\n";
  s += "#SBATCH --open-mode=append\n";
  s += fmt::format("# {} of {} over {} task(s); a re-queued task skips what it finished.\n",
                   job.parts > 0 ? fmt::format("{} strips", job.parts) : "frames " + job.frames,
                   job.parts > 0 ? fmt::format("a {}x{} still", job.still_width, job.still_height) : "the animation",
                   job.tasks);
  s += "set -euo pipefail\n";
  s += cache_line(job);
  s += "exec " + render_command(job) + "\n";
  return s;
}

std::string merge_script(const FarmJob& job) {
  std::string s = header(job, job.name + "-merge", "%x-%j.log");
  s += "#SBATCH --ntasks=1\n";
  s += "# Runs only after every part succeeded (afterok); a failed part cancels it (--kill-on-invalid-dep).\n";
  s += "set -euo pipefail\n";
  s += fmt::format("exec {} merge", shell_quote(job.sdfc));
  for (const auto& p : job.part_files) s += " " + shell_quote(p);
  s += " -o " + shell_quote(job.output) + "\n";
  return s;
}

std::string submit_script(const FarmJob& job, const std::string& array_file, const std::string& merge_file) {
  std::string s = "#!/bin/sh\n# Queues the render";
  s += job.parts > 0 ? " and, after it, the merge.\n" : ".\n";
  s += "set -eu\n";
  s += fmt::format("array=$(sbatch --parsable {})\n", shell_quote(array_file));
  s += "array=${array%%;*}\n";
  s += "echo \"render job array: $array\"\n";
  if (job.parts > 0) {
    s += fmt::format("merge=$(sbatch --parsable --dependency=afterok:\"$array\" --kill-on-invalid-dep=yes {})\n",
                     shell_quote(merge_file));
    s += "merge=${merge%%;*}\n";
    s += "echo \"merge job: $merge\"\n";
  }
  return s;
}

}  // namespace sdfc::cli
