#pragma once
// `sdfc render` on a render farm: --shard k/N picks this task's frames (or
// still parts), complete outputs are skipped so a re-queued task resumes,
// and --region / --parts render parts of a still into region files that
// `sdfc merge` joins.
#include <sdfrt/renderer.hpp>

#include <atomic>
#include <string>
#include <vector>

#include "offline_render.hpp"
#include "sdfc/ir/module.hpp"
#include "shard.hpp"

namespace CLI {
class App;
}

namespace sdfc::cli {

struct FarmArgs {
  std::string shard;                     // "k/N"
  std::string shard_mode = "contiguous";
  std::string region;                    // "x0,y0,x1,y1"
  int parts = 0;                         // split the still into this many full-width strips
  bool skip_complete = false;
  // Adds the options; call after --frames, --repeat and --keep-partial exist.
  void add_to(CLI::App& cmd);
  bool splits_still() const { return !region.empty() || parts > 0; }
  // This task's share of `count` frames or parts, as indices (all of them
  // without --shard); `sequence`: --frames was given (--shard needs it or --parts).
  IndexSlice task_slice(std::int64_t count, bool sequence = true) const;
  // True (and says so) when the frame's image and AOVs are complete files
  // already and should be skipped (--shard or --skip-complete).
  bool skip_done_frame(const OfflineOutput& out, int frame) const;
};

struct StillJob {
  sdfrt::Renderer* renderer = nullptr;
  const ir::RenderPlan* plan = nullptr;
  int width = 0, height = 0, tile = 256;
  OfflineOutput out;   // bit depth, AOVs, quiet (the beauty name is the -o pattern)
  std::string output;  // -o: a region file, or a pattern with %d per part
  std::atomic<bool>* cancel = nullptr;
};

// --region or --parts: renders this task's parts of the still to region
// files, prints their paths; returns the exit code.
int render_still_parts(const StillJob& job, const FarmArgs& farm);

}  // namespace sdfc::cli
