// Mandelbulber's hybrid mode: one orbit through several formulas, in the
// order cNineFractals::CreateSequence gives (formula_iterations_N runs of
// each slot, slots outside formula_start/stop_iteration_N skipped, back to
// repeat_from after the last). sdfc writes one period of that sequence as
// one pass of a formula chain (up to 64 steps).
#include <fmt/format.h>

#include <algorithm>

#include "import_parts.hpp"

namespace sdfc::fract {
namespace {

// The slot (0 ... 8) of each of Mandelbulber's first n iterations, as its
// CreateSequence computes them (its counter quirks included).
std::vector<int> hybrid_sequence(const Params& main, int n) {
  int formula[kFractalSlots], counts[kFractalSlots], start[kFractalSlots], stop[kFractalSlots];
  for (int k = 0; k < kFractalSlots; ++k) {
    formula[k] = main.integer(fmt::format("formula_{}", k + 1));
    counts[k] = main.integer(fmt::format("formula_iterations_{}", k + 1));
    start[k] = main.integer(fmt::format("formula_start_iteration_{}", k + 1));
    stop[k] = main.integer(fmt::format("formula_stop_iteration_{}", k + 1));
  }
  int repeat_from = std::clamp(main.integer("repeat_from"), 1, kFractalSlots);
  std::vector<int> seq;
  int no = 0, counter = 0;
  for (int i = 0; i < n; ++i) {
    ++counter;
    for (int tries = 0; (formula[no] == 0 || i < start[no] || i > stop[no]) && tries < kFractalSlots; ++tries)
      if (++no >= kFractalSlots) no = repeat_from - 1;
    seq.push_back(no);
    if (counter >= counts[no]) {
      counter = 0;
      if (++no >= kFractalSlots) no = repeat_from - 1;
    }
  }
  return seq;
}

// Top-level items of a flow list's body ("a, {b: {c, d}}" has 2).
int items(const std::string& steps) {
  int depth = 0, n = steps.empty() ? 0 : 1;
  bool quoted = false;
  for (char ch : steps) {
    if (ch == '"') quoted = !quoted;
    if (quoted) continue;
    depth += (ch == '{' || ch == '[') - (ch == '}' || ch == ']');
    n += depth == 0 && ch == ',';
  }
  return n;
}

}  // namespace

Node hybrid_chain(const Params& main, SourceLoc at, const std::function<HybridPart(int slot)>& part_of) {
  int n = std::max(main.integer("N"), 1);
  std::vector<int> seq = hybrid_sequence(main, n);
  size_t period = 1;
  while (period < seq.size() && !std::equal(seq.begin() + long(period), seq.end(), seq.begin())) ++period;
  // Without a period (formula_start/stop_iteration_N, repeat_from) the whole
  // sequence is one pass, when it fits.
  std::string steps, how;
  int cap = 1000, count = 0;
  double bailout = 0;
  for (size_t i = 0; i < period; ++i) {
    HybridPart p = part_of(seq[i] + 1);
    steps += (steps.empty() || p.part.steps.empty() ? "" : ", ") + p.part.steps;
    how += (how.empty() ? "" : " + ") + fmt::format("formula_{}", seq[i] + 1);
    cap = std::min(cap, p.part.cap);
    bailout = std::max(bailout, p.bailout);
    count += items(p.part.steps);
  }
  if (count > 64)
    fail(at, fmt::format("this hybrid sequence is not supported yet ({} steps in its period of {} iterations; sdfc's chain "
                         "takes 64)", count, period));
  int passes = (n + int(period) - 1) / int(period), cap_passes = std::max(1, cap / int(period));
  Node node{"formula", "hybrid_fractal_enable: one orbit through the formulas", {}, {}, {}};
  node.fields = {{"iterations", std::to_string(std::min(passes, cap_passes)),
                  passes <= cap_passes ? fmt::format("N = {}, {} per pass", n, period)
                                       : fmt::format("N = {} ({} per pass), sdfc's cap (no visible difference)", n, period)},
                 {"bailout", num(bailout), "bailout"},
                 {"iterate", "[" + steps + "]", "one period of the hybrid sequence: " + how}};
  return node;
}

}  // namespace sdfc::fract
