#pragma once
// sdfc render --repeat N: one warm-up frame, then N timed frames of the
// whole image in memory; prints each time and the median (what to quote),
// writes the last frame's PNG and AOVs.
#include <sdfrt/renderer.hpp>

#include <atomic>
#include <string>
#include <vector>

#include "sdfc/ir/render_plan.hpp"

namespace sdfc::cli {

struct RepeatJob {
  sdfrt::Renderer* renderer = nullptr;
  const ir::RenderPlan* plan = nullptr;
  int tile = 256;
  int repeat = 1;
  std::string output;             // a PNG
  std::vector<std::string> aovs;  // written beside it as PFMs
  std::atomic<bool>* cancel = nullptr;
};

// Returns the exit code.
int render_repeated(const RepeatJob& job);

}  // namespace sdfc::cli
