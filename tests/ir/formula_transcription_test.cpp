// Presets against Mandelbulber's own iteration, transcribed here in double
// from its formula source (Mandelbulber 2.20's formula/opencl/NAME.cl, or upstream's
// current source for formulas 2.20 lacks) with its loop (bailout after each
// iteration) and its distance estimate; the
// preset's chain is evaluated by the chain's double reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "scene_text.hpp"
#include "sdfc/formula/chain.hpp"
#include "sdfc/formula/evaluate.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc {
namespace {

using V3 = std::array<double, 3>;

const formula::Chain& chain_of(const std::string& node) {
  static std::vector<ir::Module> kept;  // the chain table outlives the module anyway
  kept.push_back(passes::run_pipeline(test::lower_text("scene: " + node + "\n")));
  const ir::Module& m = kept.back();
  for (ir::NodeId k : m.graph->postorder(m.root))
    if (m.graph->node(k).kind == ir::Kind::Formula) return formula::chain(size_t(m.graph->node(k).params[0]));
  throw std::runtime_error("no formula node");
}

// JosKleinianIteration and the josKleinian analytic estimate.
struct Jos {
  double a = 2, b = 0;  // foldingValue, offset
  V3 box{1, 1, 1};      // offset111
  bool spheres = true;
  double tweak = 0.05, min_dr = 1;  // analyticDE tweak005, offset1
  int n = 12;
  double bailout = 10;

  double distance(V3 z) const {
    double de = 1;
    const double f = b > 0 ? 1 : b < 0 ? -1 : 0;
    const V3 box1{2 * box[0], a * box[1], 2 * box[2]}, box2{-box[0], -box[1] + 1, -box[2]};
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        double x = z[k] - box2[k];
        z[k] = x - box1[k] * std::floor(x / box1[k]) + box2[k];
      }
      if (z[1] >= a * (0.5 + 0.2 * std::sin(f * M_PI * ((b * 0.5 + z[0]) / box[0])))) z = {-b - z[0], a - z[1], 0 - z[2]};
      double rr = z[0] * z[0] + z[1] * z[1] + z[2] * z[2], ir = 1 / rr;
      for (double& v : z) v *= -ir;
      z[0] = -b - z[0];
      z[1] = a + z[1];
      de *= std::fabs(ir);
      if (std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]) > bailout) break;
    }
    double y = spheres ? std::min(z[1], a - z[1]) : z[1];
    return std::min(y, tweak) / std::max(de, min_dr);
  }
};

// AmazingIfsIteration (upstream's 2021 form; 2.20 lacks it) with its
// defaults' switches: the tglad fold on x and y (z when fold_z), the scale
// over clamp(r^2, min_r2, 1), no rotation; the linear estimate r / |DE|.
struct AmazingIfs {
  double scale = 1, min_r2 = 0.25;  // scale1, minR2p25
  V3 fold{0.5, 0.5, 0.5};           // additionConstant0555
  bool fold_z = false;              // functionEnabledCzFalse
  int n = 12;
  double bailout = 100;

  double distance(V3 z) const {
    double de = 1, r = 0;
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < (fold_z ? 3 : 2); ++k) z[k] = std::fabs(z[k] + fold[k]) - std::fabs(z[k] - fold[k]) - z[k];
      double rr = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
      double dividend = rr < min_r2 ? min_r2 : std::min(rr, 1.0);
      double use = (0 + scale) / dividend;  // actualScaleA starts at 0
      for (double& v : z) v *= use;
      de = de * std::fabs(use) + 0;  // analyticDE offset0
      r = std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
      if (r > bailout) break;
    }
    return r / std::fabs(de);
  }
};

// NewtonPow3's FormulaCode (upstream's 2020 form; 2.20 lacks it) with its
// defaults' switches, in Mandelbulber's loop (aux.r is |z| before each
// iteration). Its estimate multiplies DE by 2 r per iteration, a guess the
// preset replaces by the Newton step's Jacobian, so the orbit is compared:
// |z| at the end and the iteration it stopped at.
struct NewtonPow3 {
  V3 c{-1, 0, 0}, solution{1, 0, 0};  // scaleNeg1, offsetA0, offsetB0; offset100
  double scale = 1, a1 = 1, b1 = 1;   // scale1, scaleA1, scaleB1
  int n = 12;
  double bailout = 10;

  std::pair<double, int> orbit(V3 z) const {
    double r = std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
    int i = 0;
    while (i < n && r < bailout) {
      double sq = a1 / (r * r);
      z = {z[0] * sq + solution[0], -z[1] * sq + solution[1], -z[2] * sq + solution[2]};
      V3 tp{z[0] * z[0], z[1] * z[1], z[2] * z[2]};
      sq = tp[0] + tp[1] + tp[2];
      sq = 1.0 / (3.0 * scale * sq * sq);
      double rxy = tp[0] + tp[1], h1 = 1.0 - tp[2] / rxy;
      double tx = h1 * (tp[0] - tp[1]) * sq, ty = -2.0 * h1 * z[0] * z[1] * sq, tz = 2.0 * z[2] * std::sqrt(rxy) * sq;
      double r2 = std::sqrt(tx * tx + ty * ty), r2c = std::sqrt(c[0] * c[0] + c[1] * c[1]);
      double h = 1.0 - c[2] * tz / (r2 * r2c);
      tp = {(c[0] * tx - c[1] * ty) * h, (c[1] * tx + c[0] * ty) * h, r2c * tz + r2 * c[2]};
      for (int k = 0; k < 3; ++k) z[k] = 0.6666666666 * z[k] - tp[k];
      tp = {z[0] - solution[0], z[1], z[2]};
      sq = b1 / (tp[0] * tp[0] + tp[1] * tp[1] + tp[2] * tp[2]);
      z = {tp[0] * sq, -tp[1] * sq, -tp[2] * sq};
      r = std::sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
      ++i;
    }
    return {r, i};
  }
};

// The share of random points where the preset's chain ends its orbit where
// Mandelbulber's does: the same iteration, |z| to 1e-9 relative.
double orbit_agreement(const formula::Chain& c, const NewtonPow3& mb, double half) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-half, half);
  int same = 0;
  for (int i = 0; i < 4000; ++i) {
    V3 p{u(rng), u(rng), u(rng)};
    auto [r, n] = mb.orbit(p);
    formula::OrbitResult got = formula::evaluate(c, p);
    same += int(got.iterations) == n && std::fabs(got.r - r) <= 1e-9 * std::max(1.0, r);
  }
  return same / 4000.0;
}

// The share of random points (inside the bailout ball, which cuts the
// chain's set) where the preset's
// chain gives Mandelbulber's distance to 1e-9 relative; the rest sit where
// a fold's seam or the chaotic orbit turns a last-bit difference into
// another branch.
template <class Oracle>
double agreement(const formula::Chain& c, const Oracle& mb, double half) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-half, half);
  int same = 0, n = 0;
  for (int i = 0; i < 4000; ++i) {
    V3 p{u(rng), u(rng), u(rng)};
    // Mandelbulber sets a negative distance to 0 (inside)
    double want = std::max(mb.distance(p), 0.0), got = std::max(formula::evaluate(c, p).distance, 0.0);
    same += std::fabs(got - want) <= 1e-9 * std::max(1.0, std::fabs(want));
    ++n;
  }
  return double(same) / n;
}

TEST(FormulaTranscription, JosKleinianIsMandelbulbersIterationAndEstimate) {
  Jos mb;
  EXPECT_GT(agreement(chain_of("{jos_kleinian: {iterations: 12}}"), mb, 2.5), 0.99);
  Jos other;
  other.a = 1.9, other.b = 0.073, other.box = {0.9, 1.1, 1.2}, other.spheres = false, other.tweak = 0.28, other.min_dr = 0.5;
  other.n = 20, other.bailout = 6;
  EXPECT_GT(agreement(chain_of("{jos_kleinian: {height: 1.9, shift: 0.073, box_size: [0.9, 1.1, 1.2], spheres: 0, de_cap: 0.28,"
                               " de_min_dr: 0.5, iterations: 20, bailout: 6}}"),
                      other, 2.5),
            0.99);
  other.b = -0.2;
  EXPECT_GT(agreement(chain_of("{jos_kleinian: {height: 1.9, shift: -0.2, box_size: [0.9, 1.1, 1.2], spheres: 0, de_cap: 0.28,"
                               " de_min_dr: 0.5, iterations: 20, bailout: 6}}"),
                      other, 2.5),
            0.99);
}

TEST(FormulaTranscription, AmazingIfsIsMandelbulbersIterationAndEstimate) {
  AmazingIfs mb;
  EXPECT_GT(agreement(chain_of("{amazing_ifs: {iterations: 12}}"), mb, 2.0), 0.99);
  AmazingIfs other;
  other.scale = 2.1, other.min_r2 = 0.3, other.fold = {0.7, 0.6, 0.45}, other.fold_z = true, other.n = 15;
  EXPECT_GT(agreement(chain_of("{amazing_ifs: {scale: 2.1, min_r2: 0.3, fold: [0.7, 0.6, 0.45], fold_z: 1, iterations: 15}}"),
                      other, 3.0),
            0.99);
}

TEST(FormulaTranscription, NewtonPow3IsMandelbulbersIteration) {
  NewtonPow3 mb;
  EXPECT_GT(orbit_agreement(chain_of("{newton_pow3: {iterations: 12}}"), mb, 2.0), 0.99);
  NewtonPow3 other;
  other.c = {-0.8, 0.3, 0.2}, other.solution = {1.2, 0, 0}, other.scale = 1.1, other.a1 = 0.9, other.b1 = 1.3;
  other.n = 9, other.bailout = 20;
  EXPECT_GT(orbit_agreement(chain_of("{newton_pow3: {c: [-0.8, 0.3, 0.2], solution: 1.2, scale: 1.1, pre_scale: 0.9,"
                                     " post_scale: 1.3, iterations: 9, bailout: 20}}"),
                            other, 2.0),
            0.99);
}

}  // namespace
}  // namespace sdfc
