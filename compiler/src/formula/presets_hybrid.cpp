// The built-in `hybrid:` kind's common use as a preset: a Mandelbulb step
// and a Mandelbox step, each run a number of times in a row, around again.
// One chain iteration is one hybrid step (the escape test and the orbit
// trap after every step, as the kind has them): each step's window repeats
// every bulb_repeat + box_repeat iterations.
#include <cmath>

#include "sdfc/formula/preset.hpp"

namespace sdfc::formula {
namespace {

void hybrid(const PresetArgs& a, ChainBuilder& b) {
  const int bulbs = int(std::lround(a.n("bulb_repeat"))), boxes = int(std::lround(a.n("box_repeat")));
  const int period = bulbs + boxes;
  auto window = [&](Step& s, int from, int until) {
    s.from = from;
    s.until = until;
    s.period = period;
  };
  window(b.add("bulb_power", {a.n("power")}), 0, bulbs);
  window(b.add("add_c"), 0, bulbs);
  window(b.add("box_fold", {a.n("folding_limit")}), bulbs, period);
  window(b.add("sphere_fold", {a.n("min_radius"), a.n("fixed_radius")}), bulbs, period);
  window(b.add("scale", {a.n("scale")}), bulbs, period);
  window(b.add("add_c"), bulbs, period);
  // the kind's estimator: linear r / |dr| although a power step grows faster;
  // its bailout is the ball that holds the set, its escape radius at least 100
  b.chain().de = DeChoice::Linear;
  b.chain().set_radius = a.n("set_radius");
  // the kind's bounds search believes all of its linear estimate (below the
  // log one at the escape radius); so does the preset's
  b.chain().bounds_trust = 1;
}

}  // namespace

extern const Preset kHybridPreset{
    "hybrid", "a Mandelbulb step and a Mandelbox step, each repeated, in turn (the built-in hybrid kind's two-step form)",
    {{"power", 1, {8}, 2, 32, "the Mandelbulb step's power"},
     {"bulb_repeat", 1, {1}, 1, 16, "how many Mandelbulb steps in a row (a whole number)"},
     {"scale", 1, {2}, -8, 8, "the Mandelbox step's scale"},
     {"min_radius", 1, {0.5}, 1e-6, 100, "the Mandelbox step's inner radius"},
     {"fixed_radius", 1, {1}, 1e-6, 100, "the Mandelbox step's fixed radius"},
     {"folding_limit", 1, {1}, 1e-6, 100, "the Mandelbox step's box fold half size"},
     {"box_repeat", 1, {1}, 1, 16, "how many Mandelbox steps in a row (a whole number)"},
     {"set_radius", 1, {10}, 1, 1000, "the ball that holds the set (the kind's bailout): far away the distance to it"}},
    12, 100, hybrid, "hybrid"};

}  // namespace sdfc::formula
