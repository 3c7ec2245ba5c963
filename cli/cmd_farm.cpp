// sdfc farm slurm SCENE ...: writes the Slurm job scripts that split an
// animation's frames, or a still's strips, over a job array (and merge the
// still after every part succeeded); --submit queues them. The scene is
// checked here first, so a mistake shows before anything is queued.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <sdfrt/errors.hpp>
#include <sdfrt/output_file.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sys/wait.h>

#include "cli_support.hpp"
#include "commands.hpp"
#include "offline_render.hpp"
#include "sbatch_script.hpp"
#include "sdfc/compile.hpp"

namespace sdfc::cli {
namespace {

namespace fs = std::filesystem;

struct FarmSlurmArgs {
  SceneArgs scene;
  std::string frames, still, output, partition, time, mem, script, cache_dir, sdfc;
  int parts = 0, tasks = 0, bit_depth = 8, cpus = 0;
  double fps = 30;
  std::vector<std::string> aovs;
  bool submit = false, exclusive = false;
};

// #SBATCH lines take no quoting: refuse what would break them.
void check_sbatch_value(const std::string& what, const std::string& v) {
  if (v.find_first_of(" \t\r\n'\"\\$`") != std::string::npos)
    throw std::invalid_argument(fmt::format("{} '{}': Slurm's #SBATCH lines cannot hold spaces or quotes; use a "
                                            "path or value without them", what, v));
}

// out/frame_%04d.png -> out/frame; out/still.png -> out/still
std::string base_of(const std::string& output) {
  fs::path p(output);
  std::string stem = std::regex_replace(p.stem().string(), std::regex(R"([_.-]?%0?\d*d)"), "");
  if (stem.empty()) stem = "sdfc";
  return (p.parent_path() / stem).string();
}

std::string self_path() {
  std::error_code ec;
  fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("sdfc") : p.string();
}

int run_farm_slurm(const FarmSlurmArgs& a) {
  if (a.frames.empty() == a.still.empty())
    throw std::invalid_argument("sdfc farm slurm: give --frames FIRST:LAST (an animation) or --still WxH --parts N");
  FarmJob job;
  const fs::path cwd = fs::current_path();
  job.workdir = cwd.string();
  job.scene = fs::absolute(a.scene.path).string();
  job.output = fs::absolute(a.output).lexically_normal().string();
  for (const auto& s : a.scene.sets) job.render_args.insert(job.render_args.end(), {"--set", s});
  if (!a.aovs.empty()) {
    std::string list;
    for (const auto& v : a.aovs) list += (list.empty() ? "" : ",") + v;
    job.render_args.insert(job.render_args.end(), {"--aov", list});
  }
  if (a.bit_depth != 8) job.render_args.insert(job.render_args.end(), {"--bit-depth", std::to_string(a.bit_depth)});
  // The scene must load with its overrides before anything is queued.
  std::vector<std::string> sets = a.scene.sets;
  std::int64_t frame_count = 0;
  if (!a.still.empty()) {
    std::smatch m;
    static const std::regex re(R"(^(\d{1,5})x(\d{1,5})$)");
    if (!std::regex_match(a.still, m, re))
      throw std::invalid_argument(fmt::format("--still '{}': expected WIDTHxHEIGHT, e.g. 16384x16384", a.still));
    job.still_width = std::stoi(m[1]), job.still_height = std::stoi(m[2]);
    sets.push_back(fmt::format("render.width={}", job.still_width));
    sets.push_back(fmt::format("render.height={}", job.still_height));
    if (a.parts < 1) throw std::invalid_argument("--still needs --parts N: how many strips to cut the image into");
    if (a.parts > job.still_height)
      throw std::invalid_argument(fmt::format("--parts {}: a {}-row image has at most {} strips", a.parts,
                                              job.still_height, job.still_height));
    job.parts = a.parts;
    frame_count = a.parts;
  } else {
    if (a.parts > 0) throw std::invalid_argument("--parts splits a --still; an animation is split by its frames");
    job.frames = a.frames;
    frame_count = parse_frames(a.frames).size();
    if (frame_count > 1 && !has_frame_field(a.output))
      throw std::invalid_argument(fmt::format(
          "-o '{}': {} frames need one frame-number field in the name, e.g. out/frame_%04d.png "
          "(write %% for a '%')", a.output, frame_count));
    if (a.fps != 30) job.render_args.insert(job.render_args.end(), {"--fps", fmt::format("{}", a.fps)});
  }
  build_module(load_scene_source(a.scene.path, sets), a.scene.path);
  job.tasks = a.tasks > 0 ? a.tasks : int(std::min<std::int64_t>(frame_count, 1000));
  if (job.tasks > frame_count)
    throw std::invalid_argument(fmt::format("--tasks {}: there are only {} {} to share", job.tasks, frame_count,
                                            job.parts > 0 ? "parts" : "frames"));
  job.partition = a.partition, job.time = a.time, job.mem = a.mem;
  job.cpus_per_task = a.cpus, job.exclusive = a.exclusive;
  const std::string base = fs::absolute(a.script.empty() ? base_of(a.output) : a.script).lexically_normal().string();
  job.name = "sdfc-" + fs::path(base).filename().string();
  job.log_dir = base + ".logs";
  // A '%' of the output's name is "%%" in the pattern (frame_path makes it one again).
  job.parts_pattern = std::regex_replace(base, std::regex("%"), "%%") + ".parts/part_%03d.region";
  const fs::path parts_dir = base + ".parts";
  for (int k = 0; k < job.parts; ++k) job.part_files.push_back(frame_path(job.parts_pattern, k));
  job.cache_dir = fs::absolute(a.cache_dir.empty() ? fs::path(base).parent_path() / "sdfc-kernel-cache" : fs::path(a.cache_dir))
                      .lexically_normal()
                      .string();
  job.sdfc = a.sdfc.empty() ? self_path() : a.sdfc;
  for (const auto& [what, v] : {std::pair<std::string, std::string>{"--partition", job.partition},
                                {"--time", job.time}, {"--mem", job.mem}, {"the working directory", job.workdir},
                                {"--script", job.log_dir}, {"--script", job.name}, {"--cache-dir", job.cache_dir}})
    check_sbatch_value(what, v);

  for (const fs::path& dir : {fs::path(job.log_dir), parts_dir, fs::path(job.output).parent_path()}) {
    std::error_code ec;
    if (job.parts == 0 && dir == parts_dir) continue;
    fs::create_directories(dir, ec);
    if (ec) throw sdfrt::IoError(fmt::format("cannot create '{}': {}", dir.string(), ec.message()), dir.string(), ec.value());
  }
  const std::string array_file = base + ".sbatch", merge_file = base + ".merge.sbatch", submit_file = base + ".submit.sh";
  auto write = [](const std::string& path, const std::string& text) {
    sdfrt::write_output_file(path, text);
    std::cout << path << "\n";
  };
  write(array_file, array_script(job));
  if (job.parts > 0) write(merge_file, merge_script(job));
  write(submit_file, submit_script(job, array_file, merge_file));
  if (!a.submit) {
    std::cerr << fmt::format("queue it with: sh {}\n", shell_quote(submit_file));
    return kOk;
  }
  std::cout << std::flush;
  const int status = std::system(("sh " + shell_quote(submit_file)).c_str());
  if (status != 0) {
    std::cerr << fmt::format("sdfc: submitting failed ({}); is Slurm reachable (sinfo)?\n",
                             WIFEXITED(status) ? fmt::format("exit {}", WEXITSTATUS(status)) : "killed");
    return kDeviceError;
  }
  return kOk;
}

}  // namespace

Action add_farm(CLI::App& app) {
  auto* farm = app.add_subcommand("farm", "Split a render over a cluster's job scheduler");
  farm->require_subcommand(1);
  auto* cmd = farm->add_subcommand(
      "slurm", "Write Slurm job scripts: a job array rendering frames (or a still's strips, then a merge job)");
  auto a = std::make_shared<FarmSlurmArgs>();
  a->scene.add_to(*cmd);
  auto* frames = cmd->add_option("--frames", a->frames, "An animation's frames, FIRST:LAST (as for sdfc render)");
  auto* still = cmd->add_option("--still", a->still, "A still of WIDTHxHEIGHT pixels, cut into --parts strips");
  frames->excludes(still);
  cmd->add_option("--parts", a->parts, "A still's full-width strips (region files, merged at the end)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--tasks", a->tasks, "Array tasks (default: one per frame or part, at most 1000)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--partition", a->partition, "Slurm partition (default: the cluster's)");
  cmd->add_option("--time", a->time, "Time limit per task, e.g. 02:00:00");
  cmd->add_option("--mem", a->mem, "Memory per task, e.g. 4G");
  cmd->add_option("--cpus-per-task", a->cpus, "CPUs per task (the CPU device renders on every core it is given)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--exclusive", a->exclusive, "A whole node per task (the fastest for CPU rendering)");
  cmd->add_option("-o,--output", a->output,
                  "The images: a pattern such as out/frame_%04d.png, or a still's PNG (out/print.png)")
      ->required();
  cmd->add_option("--aov", a->aovs, "AOVs to write too (as for sdfc render)")->delimiter(',')->check(CLI::IsMember(kAovNames));
  cmd->add_option("--bit-depth", a->bit_depth, "PNG bits per channel: 8 or 16")->check(CLI::IsMember({8, 16}));
  cmd->add_option("--fps", a->fps, "Frames per second for --frames (default 30)")
      ->check(CLI::Range(0.001, 10000.0))
      ->check(finite_number());
  cmd->add_option("--script", a->script,
                  "Where the scripts go, without extension (default: beside -o, e.g. out/frame.sbatch)");
  cmd->add_option("--cache-dir", a->cache_dir,
                  "Kernel binary cache on shared storage for every task (default: sdfc-kernel-cache beside -o)");
  cmd->add_option("--sdfc", a->sdfc, "The sdfc the tasks run (default: this one, by absolute path)");
  cmd->add_flag("--submit", a->submit, "Queue the jobs now (runs the submit script, which calls sbatch)");
  return [a, cmd] { return cmd->parsed() ? run_farm_slurm(*a) : kUsageError; };
}

}  // namespace sdfc::cli
