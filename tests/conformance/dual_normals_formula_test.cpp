// render.normals: dual through formula chains, for every example in
// examples/formulas: either the chain's estimate is differentiated (its dual
// normal agrees with a fine central difference of the same kernel's
// scene_dist at the surface points the example's camera sees), or the scene
// is refused with an error that names why (a step without a rule, or a
// running-Jacobian estimate).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "normal_probe.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "sdfc/support/diagnostics.hpp"
#include "sdfc_test_support.hpp"
#include "test_files.hpp"

namespace sdfc {
namespace {

using test::V3;

std::vector<std::string> formula_examples() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SDFC_SOURCE_DIR) + "/examples/formulas"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool has_formula(const ir::Module& m) {
  for (ir::NodeId id : m.graph->postorder(m.root))
    if (m.graph->node(id).kind == ir::Kind::Formula) return true;
  return false;
}

V3 unit(const V3& v) { return test::mul(v, 1.0 / std::sqrt(test::dot(v, v))); }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Surface points the camera sees: rays through random points of the middle
// of the view, traced on the reference at half steps (some examples'
// estimates overshoot at full steps).
std::vector<V3> seen_points(const ir::Module& m, size_t want, std::mt19937_64& rng) {
  const ir::Camera& cam = m.plan.camera;
  const V3 o{cam.position[0], cam.position[1], cam.position[2]};
  const V3 fwd = unit(test::sub({cam.target[0], cam.target[1], cam.target[2]}, o));
  const V3 right = unit(cross(fwd, {cam.up[0], cam.up[1], cam.up[2]})), up = cross(right, fwd);
  const double half = std::tan(cam.fov_degrees * std::numbers::pi / 360) * 0.7;
  std::uniform_real_distribution<double> u(-half, half);
  auto f = [&](const V3& x) { return 0.5 * reference::distance(m, x); };
  std::vector<V3> pts;
  for (size_t attempt = 0; attempt < 4 * want && pts.size() < want; ++attempt) {
    const V3 rd = unit(test::add(fwd, test::add(test::mul(right, u(rng)), test::mul(up, u(rng)))));
    if (auto t = test::trace_to_surface(f, o, rd, 1e-4, m.plan.march.max_distance)) pts.push_back(test::add(o, test::mul(rd, *t)));
  }
  return pts;
}

class DualNormalsFormula : public ::testing::TestWithParam<std::string> {};

TEST_P(DualNormalsFormula, AgreesWithCentralDifferencesOrIsRefusedWithItsReason) {
  const std::string name = GetParam();
  const std::string text = test::read_text_file(std::string(SDFC_SOURCE_DIR) + "/examples/formulas/" + name + ".yaml");
  std::optional<ir::Module> m;
  try {
    m = test::compile_text(text, name + ".yaml", {"render.normals=dual", "render.precision=double"});
  } catch (const SceneError& e) {
    const std::string what = e.what();
    fmt::print("[dual-normals] {:<22}: refused: {}\n", name, what.substr(0, what.find('\n')));
    // A preset that renders as a built-in kind without dual derivatives
    // (menger, sierpinski) is refused by that kind's own rule.
    if (what.find("dual needs dual-number derivatives, which '") != std::string::npos) GTEST_SKIP() << what;
    EXPECT_NE(what.find("render.normals: dual cannot differentiate"), std::string::npos) << what;
    EXPECT_TRUE(what.find("(line ") != std::string::npos || what.find("de: jacobian") != std::string::npos) << what;
    return;
  }
  if (!has_formula(*m)) GTEST_SKIP() << name << " renders with a built-in kind (its dual normals: dual_normals_test)";
  std::mt19937_64 rng(7);
  const std::vector<V3> pts = seen_points(*m, 200, rng);
  ASSERT_GE(pts.size(), 100u) << name;
  const int width = 8;
  std::vector<float> out = test::run_point_kernel(normal_kernel(*m, width, "1e-7"), "normal_probe", pts, width);
  std::vector<double> angle;
  for (float c : out) angle.push_back(std::acos(std::clamp(double(c), -1.0, 1.0)) * 180 / std::numbers::pi);
  std::sort(angle.begin(), angle.end());
  const size_t within = size_t(std::lower_bound(angle.begin(), angle.end(), 1.0) - angle.begin());
  fmt::print("[dual-normals] {:<22}: {} hits, median angle to central differences {:.4f} deg, {:.1f} % within 1 deg\n", name,
             pts.size(), angle[angle.size() / 2], 100.0 * double(within) / double(pts.size()));
  EXPECT_LT(angle[angle.size() / 2], 0.1) << name;
  EXPECT_GE(double(within), 0.9 * double(pts.size())) << name;
}

INSTANTIATE_TEST_SUITE_P(Examples, DualNormalsFormula, ::testing::ValuesIn(formula_examples()),
                         [](const auto& info) { return info.param; });

TEST(DualNormalsFormulaErrors, AnExprChainIsRefusedNamingItsStep) {
  try {
    test::compile_text(
        "render: {normals: dual}\n"
        "scene:\n"
        "  formula:\n"
        "    iterate:\n"
        "      - expr: {x: \"x*x - y*y - z*z\", y: \"2*x*y\", z: \"-2*x*z\"}\n"
        "      - add_c\n");
    FAIL() << "expected a scene error";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("1:19"), std::string::npos) << what;
    EXPECT_NE(what.find("step expr (line 5) is not conformal"), std::string::npos) << what;
    EXPECT_NE(what.find("normals: central"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace sdfc
