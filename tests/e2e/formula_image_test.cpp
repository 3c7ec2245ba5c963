// Formula chains rendered on the device: a fractal written only as `expr`
// steps against the same fractal written with its power step.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "e2e_support.hpp"
#include "sdfc/compile.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::e2e {
namespace {

sdfrt::FloatImage render_example(const std::string& name, std::vector<std::string> sets) {
  const std::string path = (std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / "formulas" / name).string();
  SourceValue doc = load_yaml_file(path);
  sets.insert(sets.end(), {"render.width=320", "render.height=180"});
  apply_overrides(doc, sets);
  return render(build_module(doc, path), 8);
}

// The share of pixels whose colour differs by more than 4/255 in a channel.
double differing(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  size_t n = a.plane_size(), off = 0;
  for (size_t i = 0; i < n; ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      float x = std::clamp(a.data[size_t(c) * n + i], 0.0f, 1.0f), y = std::clamp(b.data[size_t(c) * n + i], 0.0f, 1.0f);
      differs = differs || std::fabs(x - y) > 4.0f / 255.0f;
    }
    off += differs;
  }
  return double(off) / double(n);
}

// The power-2 bulb as expressions (Cartesian, differentiated symbolically)
// against bulb_power: 2 with the same estimator (the running Jacobian): the
// expr machinery must reproduce the power step's image.
TEST(FormulaImage, ExprBulb2MatchesBulbPower2) {
  sdfrt::FloatImage expr = render_example("bulb2_expr.yaml", {});
  sdfrt::FloatImage power = render_example("bulb2.yaml", {"scene.formula.de=jacobian"});
  double share = differing(expr, power);
  fmt::print("[formula-image] bulb2_expr vs bulb_power 2 (de: jacobian): {:.3f} % of pixels differ by > 4/255\n", 100 * share);
  EXPECT_LE(share, 0.005);
  // With its own (scalar) derivative the power step's image is recorded, not held.
  sdfrt::FloatImage scalar = render_example("bulb2.yaml", {});
  fmt::print("[formula-image] bulb2_expr vs bulb_power 2 (scalar derivative): {:.3f} % differ\n", 100 * differing(expr, scalar));
}

// The julia preset's chain (a 4-D chain: quaternion, add_c) against the
// built-in julia: node it spells out, in the preset's example view. Left to
// itself the preset renders with the node's code; `de: log` (the estimate
// the compiler chooses for the chain anyway) keeps the chain.
TEST(FormulaImage, JuliaPresetMatchesBuiltinJulia) {
  const std::string node = "julia: {c: [-0.2, 0.6, 0.2, 0.2], degree: 2, iterations: 12, slice: 0}";
  sdfrt::FloatImage preset = render_example("julia_preset.yaml", {"scene.formula.de=log"});
  std::string path = (std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / "formulas" / "julia_preset.yaml").string();
  SourceValue doc = load_yaml_file(path);
  apply_overrides(doc, {"render.width=320", "render.height=180"});
  // the built-in node in the formula's place, the material kept
  std::string yaml = "scene:\n  " + node + "\n";
  SourceValue scene = load_yaml_text(yaml, "builtin.yaml");
  for (auto& [k, v] : doc.entries)
    if (k.scalar == "scene")
      for (auto& [sk, sv] : v.entries)
        if (sk.scalar == "formula") {
          sk = scene.find("scene")->entries[0].first;
          sv = scene.find("scene")->entries[0].second;
        }
  ir::Module kind = build_module(doc, path);
  bool has_kind = false;  // the built-in node, not the chain, is what renders
  for (ir::NodeId id : kind.graph->postorder(kind.root)) has_kind = has_kind || kind.graph->node(id).kind == ir::Kind::QuaternionJulia;
  ASSERT_TRUE(has_kind);
  sdfrt::FloatImage builtin = render(std::move(kind), 8);
  double share = differing(preset, builtin);
  fmt::print("[formula-image] julia preset vs built-in julia: {:.3f} % of pixels differ by > 4/255\n", 100 * share);
  EXPECT_LE(share, 0.005);
}

// The hybrid preset against the built-in hybrid kind it spells out, on the
// kind's example view (examples/hybrid.yaml's camera, lights and orbit-trap
// material): the same orbit step for step, the same escape radius and the
// same linear estimate, so the images must agree.
TEST(FormulaImage, HybridPresetMatchesTheHybridKind) {
  const std::string path = (std::filesystem::path(SDFC_SOURCE_DIR) / "examples" / "formulas" / "hybrid_preset.yaml").string();
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string kind = text.str();
  const size_t at = kind.find("  formula: {preset: hybrid");
  ASSERT_NE(at, std::string::npos);
  kind.replace(at, kind.find('\n', at) - at,
               "  hybrid: {steps: [{mandelbulb: {power: 8}}, {mandelbox: {scale: 2, min_radius: 0.5, fixed_radius: 1, "
               "folding_limit: 1}}], repeat: [1, 2], iterations: 12, bailout: 4}");
  SourceValue doc = load_yaml_text(kind, "hybrid-kind.yaml");
  apply_overrides(doc, {"render.width=320", "render.height=180"});
  sdfrt::FloatImage builtin = render(build_module(doc, "hybrid-kind.yaml"), 8);
  sdfrt::FloatImage preset = render_example("hybrid_preset.yaml", {});
  double share = differing(preset, builtin);
  fmt::print("[formula-image] hybrid preset vs hybrid kind: {:.3f} % of pixels differ by > 4/255\n", 100 * share);
  EXPECT_LE(share, 0.005);
}

}  // namespace
}  // namespace sdfc::e2e
