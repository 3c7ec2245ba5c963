// Every formula step's derivative rule against central differences of its
// own double evaluation: the Jacobian columns it carries must be dz'/dz,
// and for a conformal step (not a power, whose dr is the usual bound) the
// scalar factor must be |dz'/dz| (the
// Frobenius norm of a similarity is sqrt(3) times its factor).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "sdfc/formula/step.hpp"

namespace sdfc::formula {
namespace {

Step make(const StepDef& d, std::vector<double> a = {}) {
  Step st;
  st.def = &d;
  size_t at = 0;
  for (const StepParam& q : d.params) {
    if (a.size() <= at) a.insert(a.end(), q.fallback.begin(), q.fallback.begin() + q.width);
    at += size_t(q.width);
  }
  st.a = a;
  return st;
}

V3 stepped(const Step& st, const V3& z) {
  RefState s;
  s.z = z;
  s.c = {0, 0, 0};
  s.mandel = false;
  st.def->eval(st, s);
  return s.z;
}

// The steps to check, with settings that exercise every branch.
std::vector<Step> cases() {
  std::vector<Step> v;
  for (const StepDef* d : steps()) {
    if (d->name == "expr") continue;  // its partials are checked by the expression tests
    if (d->name == "spherical_invert") {
      v.push_back(make(*d, {1.3, 0.1, 0.2, -0.1}));
    } else if (d->name == "surf_fold") {
      v.push_back(make(*d, {0.7, 0.8, 0.9, 1, 1, 0}));
      v.push_back(make(*d, {0.7, 0.8, 0.9, 1, 1, 1}));
    } else if (d->name == "polyfold") {
      v.push_back(make(*d, {3}));
      v.push_back(make(*d, {5}));
    } else if (d->name == "polyhedral_fold") {
      for (int type = 0; type < 8; ++type) v.push_back(make(*d, {double(type)}));
    } else if (d->name == "plane_fold") {
      v.push_back(make(*d, {1, 1, 0, 0.2}));
    } else if (d->name == "quaternion") {
      v.push_back(make(*d, {2}));
      v.push_back(make(*d, {3}));
    } else if (d->name == "triplex_newton") {
      v.push_back(make(*d));
      v.push_back(make(*d, {-0.8, 0.3, 0.2, 1.1}));
      v.push_back(make(*d, {0, 0, 0.5, 1}));  // c on the z axis
    } else if (d->name == "rotate") {
      v.push_back(make(*d, {1, 0, 1, 30}));
    } else {
      v.push_back(make(*d));
    }
  }
  return v;
}

TEST(FormulaStepDerivative, EveryStepCarriesItsJacobianAndConformalFactor) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  const double h = 1e-6;
  for (const Step& st : cases()) {
    SCOPED_TRACE(std::string(st.def->name));
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
      const V3 z{u(rng), u(rng), u(rng)};
      RefState s;
      s.z = z;
      s.c = {0, 0, 0};
      s.mandel = false;
      st.def->eval(st, s);
      // Central differences at h and 2h; points where they disagree sit on a
      // fold's seam, where the derivative jumps.
      bool smooth = true;
      std::array<V3, 3> fd{};
      for (int k = 0; k < 3 && smooth; ++k) {
        V3 a = z, b = z, a2 = z, b2 = z;
        a[k] += h, b[k] -= h, a2[k] += 2 * h, b2[k] -= 2 * h;
        V3 pa = stepped(st, a), pb = stepped(st, b), qa = stepped(st, a2), qb = stepped(st, b2);
        for (int r = 0; r < 3; ++r) {
          double d1 = (pa[r] - pb[r]) / (2 * h), d2 = (qa[r] - qb[r]) / (4 * h);
          if (std::fabs(d1 - d2) > 1e-4 * std::max(1.0, std::fabs(d1))) smooth = false;
          fd[k][r] = d1;
        }
      }
      if (!smooth) continue;
      ++checked;
      double norm = 0;
      for (int k = 0; k < 3; ++k)
        for (int r = 0; r < 3; ++r) {
          ASSERT_NEAR(s.j[k][r], fd[k][r], 1e-5 * std::max(1.0, std::fabs(fd[k][r])))
              << "column " << k << " row " << r << " at " << z[0] << ", " << z[1] << ", " << z[2];
          norm += fd[k][r] * fd[k][r];
        }
      if (st.def->conformal(st) && !st.def->power && st.def->name != "kleinian_fold" && !st.def->four_d) {  // 4-D: the next test
        EXPECT_NEAR(s.dr, std::sqrt(norm / 3), 1e-5 * std::max(1.0, s.dr)) << "the scalar factor";
      }
    }
    EXPECT_GT(checked, 200);
  }
}

// A 4-D step: (z, w) -> (z', w'). The columns it carries start as dz/dp =
// I, dw/dp = 0 (rows x, y, z, w of columns x, y, z), then as dz/dp = 0,
// dw/dp = (1, 0, 0): its first column is then the step's w column.
std::array<double, 4> stepped4(const Step& st, const std::array<double, 4>& q) {
  RefState s;
  s.z = {q[0], q[1], q[2]};
  s.w = q[3];
  s.c = {0, 0, 0};
  s.mandel = false;
  s.four_d = true;
  st.def->eval(st, s);
  return {s.z[0], s.z[1], s.z[2], s.w};
}

TEST(FormulaStepDerivative, EveryFourDStepCarriesItsJacobianWithTheWRow) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  const double h = 1e-6;
  int steps_checked = 0;
  for (const Step& st : cases()) {
    if (!st.def->four_d) continue;
    SCOPED_TRACE(std::string(st.def->name));
    ++steps_checked;
    int checked = 0;
    for (int i = 0; i < 400; ++i) {
      const std::array<double, 4> q{u(rng), u(rng), u(rng), u(rng)};
      std::array<std::array<double, 4>, 4> fd{};  // fd[k][r]: d new_r / d q_k
      bool smooth = true;
      for (int k = 0; k < 4 && smooth; ++k) {
        auto a = q, b = q, a2 = q, b2 = q;
        a[k] += h, b[k] -= h, a2[k] += 2 * h, b2[k] -= 2 * h;
        auto pa = stepped4(st, a), pb = stepped4(st, b), qa = stepped4(st, a2), qb = stepped4(st, b2);
        for (int r = 0; r < 4; ++r) {
          double d1 = (pa[r] - pb[r]) / (2 * h), d2 = (qa[r] - qb[r]) / (4 * h);
          if (std::fabs(d1 - d2) > 1e-4 * std::max(1.0, std::fabs(d1))) smooth = false;
          fd[k][r] = d1;
        }
      }
      if (!smooth) continue;
      ++checked;
      RefState s;
      s.z = {q[0], q[1], q[2]};
      s.w = q[3];
      s.c = {0, 0, 0};
      s.mandel = false;
      s.four_d = true;
      st.def->eval(st, s);
      double norm = 0;
      for (int k = 0; k < 3; ++k)
        for (int r = 0; r < 4; ++r) {
          ASSERT_NEAR(r < 3 ? s.j[k][r] : s.jw[k], fd[k][r], 1e-5 * std::max(1.0, std::fabs(fd[k][r]))) << "column " << k << " row " << r;
          norm += fd[k][r] * fd[k][r];
        }
      if (st.def->conformal(st) && !st.def->power) {
        EXPECT_NEAR(s.dr, std::sqrt(norm / 3), 1e-5 * std::max(1.0, s.dr));
      }
      RefState t;
      t.z = {q[0], q[1], q[2]};
      t.w = q[3];
      t.c = {0, 0, 0};
      t.mandel = false;
      t.four_d = true;
      t.j = {V3{0, 0, 0}, V3{0, 0, 0}, V3{0, 0, 0}};
      t.jw = {1, 0, 0};
      st.def->eval(st, t);
      for (int r = 0; r < 4; ++r)
        ASSERT_NEAR(r < 3 ? t.j[0][r] : t.jw[0], fd[3][r], 1e-5 * std::max(1.0, std::fabs(fd[3][r]))) << "the w column, row " << r;
    }
    EXPECT_GT(checked, 200);
  }
  EXPECT_GE(steps_checked, 4);  // quaternion, hypercomplex, quadray, aexion
}

// kleinian_fold's scalar factor is the inversion's plus de_tweak.
TEST(FormulaStepDerivative, KleinianFoldTakesTheTweakOnItsScalarFactor) {
  const StepDef* d = find_step("kleinian_fold");
  ASSERT_NE(d, nullptr);
  RefState s;
  s.z = {0.3, 0.2, 0.1};
  s.mandel = false;
  d->eval(make(*d, {0.5, 0.05}), s);
  EXPECT_NEAR(s.dr, 0.5 / 0.14 + 0.05, 1e-12);  // r^2 = 0.14 < min_r2: k = 0.5 / 0.14
}

}  // namespace
}  // namespace sdfc::formula
