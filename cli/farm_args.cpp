#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <iostream>

#include "farm_render.hpp"

namespace sdfc::cli {
namespace {

// A CLI11 check from a parser that throws std::invalid_argument, so bad
// values are refused before the kernel is built.
template <class Parse>
CLI::Validator checked_by(Parse parse) {
  return CLI::Validator(
      [parse](std::string& v) {
        try {
          parse(v);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      },
      "");
}

}  // namespace

void FarmArgs::add_to(CLI::App& cmd) {
  auto* sh = cmd.add_option("--shard", shard,
                            "Render only task K's share (0-based) of N: of --frames, or of the still's --parts "
                            "(e.g. --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT); outputs that are already "
                            "complete are skipped, so a re-queued task resumes")
                ->check(checked_by(parse_shard));
  cmd.add_option("--shard-mode", shard_mode,
                 "How --shard splits: contiguous (a run of neighbouring frames, the default) or strided (every N-th)")
      ->needs(sh)
      ->check(checked_by(parse_shard_mode));
  auto* rg = cmd.add_option("--region", region,
                            "Render only the pixels X0,Y0,X1,Y1 of the still into a region file (-o PART.region); "
                            "'sdfc merge' joins the parts into the image")
                ->check(checked_by([](const std::string& v) { parse_region(v, 1 << 30, 1 << 30); }));
  auto* pt = cmd.add_option("--parts", parts,
                            "Split the still into N full-width strips, each a region file (-o with a field: "
                            "out/part_%03d.region); with --shard only this task's parts")
                 ->check(CLI::Range(1, 16384));
  rg->excludes(pt);
  cmd.add_flag("--skip-complete", skip_complete,
               "Skip frames (or parts) whose files already exist complete (implied by --shard)");
  for (const char* other : {"--frames", "--repeat", "--keep-partial"})
    if (auto* o = cmd.get_option_no_throw(other)) rg->excludes(o), pt->excludes(o);
}

IndexSlice FarmArgs::task_slice(std::int64_t count, bool sequence) const {
  if (shard.empty()) return {0, count, 1};
  if (!sequence)
    throw std::invalid_argument(fmt::format("--shard {}: nothing to split; give --frames FIRST:LAST (an animation) or "
                                            "--parts N (a still)", shard));
  return shard_slice(count, parse_shard(shard), parse_shard_mode(shard_mode));
}

bool FarmArgs::skip_done_frame(const OfflineOutput& out, int frame) const {
  if (shard.empty() && !skip_complete) return false;
  if (!output_complete(out.beauty)) return false;
  for (const auto& a : out.aovs)
    if (!output_complete(aov_path(out.beauty, a))) return false;
  if (!out.quiet) std::cerr << fmt::format("frame {}: {} is complete already, skipped\n", frame, out.beauty);
  return true;
}

}  // namespace sdfc::cli
