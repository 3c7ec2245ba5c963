// Where sphere tracing fails, shown on real kernels (PoCL) against the
// reference render (ir::make_reference: double, 0.01 px, bisection), and the
// fix for each: the audit's step factor against overshoot, the footprint-
// scaled normal step against float noise, more steps against grazing holes.
#include <gtest/gtest.h>
#include <sdfrt/image_metrics.hpp>
#include <sdfrt/renderer.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <iostream>

#include "sdfc/analysis/audit.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc {
namespace {

using Tweak = std::function<void(ir::Module&)>;

// Renders the scene at 96x54 (after `tweak`) with the AOVs, split into the
// images sdfrt::compare_renders reads.
sdfrt::RenderOutputs render(const std::string& yaml, const Tweak& tweak) {
  ir::Module m = test::compile_text(yaml);
  m.plan.march.width = 96;
  m.plan.march.height = 54;
  tweak(m);
  codegen::EmitOptions eo;
  eo.simd_width = 16;
  eo.aovs = true;
  codegen::EmittedKernel k = codegen::emit_opencl(m, eo);
  sdfrt::Renderer r(test::device(), sdfrt::KernelSpec{.source = k.source,
                                                      .entry = k.entry,
                                                      .simd_width = k.simd_width,
                                                      .packet_rows = k.packet_rows,
                                                      .planes = k.planes});
  const int w = m.plan.march.width, h = m.plan.march.height;
  sdfrt::FloatImage img = r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h);
  auto take = [&](std::vector<std::string> names, std::vector<std::string> as) {
    sdfrt::FloatImage out(w, h, as);
    for (size_t c = 0; c < names.size(); ++c) {
      int p = img.plane_index(names[c]);
      EXPECT_GE(p, 0) << names[c];
      std::copy(img.plane(p).begin(), img.plane(p).end(), out.plane(int(c)).begin());
    }
    return out;
  };
  sdfrt::RenderOutputs o;
  o.beauty = take({"r", "g", "b"}, {"r", "g", "b"});
  o.depth = take({"depth"}, {"depth"});
  o.normal = take({"normal_x", "normal_y", "normal_z"}, {"normal.x", "normal.y", "normal.z"});
  return o;
}

sdfrt::ComparisonMetrics against_reference(const std::string& yaml, const Tweak& tweak, const Tweak& ref_tweak = {}) {
  auto ref = render(yaml, [&](ir::Module& m) {
    ir::make_reference(m.plan.march);
    if (ref_tweak) ref_tweak(m);
  });
  auto m = sdfrt::compare_renders(ref, render(yaml, tweak));
  std::cout << sdfrt::format_table(m);
  return m;
}

// The smallest step factor the audit recommends over the scene's nodes.
double audit_step_factor(const std::string& yaml) {
  analysis::AuditOptions opt;
  opt.rays = 96;
  auto r = analysis::audit(test::compile_text(yaml), opt);
  double f = 1.0;
  for (const auto& n : r.nodes) f = std::min(f, n.recommended_step_factor);
  return f;
}

constexpr const char* kLight = "lights:\n  - directional: {direction: [-0.5, 0.55, -0.67]}\n";

// Seed 001 part VII: the scalar DE of the non-conformal Mandelbox overshoots
// (rays land behind the reference's surface or pass through it); the step
// factor the audit recommends brings that back to the level of the
// conformal DE. The reference uses the Jacobian DE, which is right here.
TEST(Stability, NonConformalMandelboxOvershootsUntilTheAuditsStepFactor) {
  const std::string scene = std::string("camera: {position: [5.5, -6.5, 4.0], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n") +
                            kLight + "scene: {mandelbox: {scale: 2, iterations: 12, scale_xyz: [1.0, 1.6, 0.7]}}\n";
  const std::string ref_scene = scene.substr(0, scene.size() - 3) + ", de: jacobian}}\n";
  const double f = audit_step_factor(scene);
  ASSERT_LT(f, 1.0);
  auto ref = render(ref_scene, [](ir::Module& m) { ir::make_reference(m.plan.march); });
  auto raw = sdfrt::compare_renders(ref, render(scene, [](ir::Module&) {}));
  auto fixed = sdfrt::compare_renders(ref, render(scene, [&](ir::Module& m) { m.plan.march.step_factor = f; }));
  std::cout << "scalar DE, step 1:\n" << sdfrt::format_table(raw) << "step " << f << ":\n" << sdfrt::format_table(fixed);
  EXPECT_GT(raw.passed_pct, 1.0);
  EXPECT_LT(fixed.passed_pct, 0.5 * raw.passed_pct);
}

// A twist and a displacement without the Lipschitz correction overshoot; the
// audit's step factor or the correction removes it.
TEST(Stability, UncorrectedTwistAndDisplaceOvershootUntilTheAuditsStepFactor) {
  const std::string body = std::string("camera: {position: [0.6, -4.6, 1.6], target: [0.6, 0, 0], up: [0, 0, 1], fov: 38}\n") + kLight +
                           "scene:\n  union:\n"
                           "    - {box: {size: [0.6, 0.6, 2.0], radius: 0.03}, twist: {axis: z, rate: 3}, translate: [-0.4, 0, 0]}\n"
                           "    - {sphere: {radius: 0.75}, displace: {expr: \"0.1*sin(15*x)*sin(15*y)*sin(15*z)\"}, translate: [1.6, 0, 0]}\n";
  const std::string raw_scene = "render: {lipschitz_correction: false}\n" + body;
  const double f = audit_step_factor(raw_scene);
  ASSERT_LT(f, 1.0);
  auto raw = against_reference(raw_scene, [](ir::Module&) {}, [](ir::Module& m) { m.plan.march.step_factor = 0.05; });
  auto fixed = against_reference(raw_scene, [&](ir::Module& m) { m.plan.march.step_factor = f; },
                                 [](ir::Module& m) { m.plan.march.step_factor = 0.05; });
  auto corrected = against_reference(body, [](ir::Module&) {});
  EXPECT_GT(raw.passed_pct, 1.0);
  EXPECT_LT(fixed.passed_pct, 0.2 * raw.passed_pct);
  EXPECT_LT(corrected.passed_pct, 0.2 * raw.passed_pct);
}

// Finite differences with a step far below float resolution (1e-6 of a
// pixel footprint, ~1e-8 here, where a float at |p| ~ 3 resolves 2.4e-7)
// give noise; the same step in double, or the footprint-scaled default
// (half a pixel) in float, does not.
TEST(Stability, TinyNormalStepIsNoisyInFloat) {
  const std::string scene = std::string("camera: {position: [3, -3, 0.5], target: [3, 0, 0], up: [0, 0, 1], fov: 40}\n") + kLight +
                            "scene: {sphere: {radius: 0.8}, translate: [3, 0, 0]}\n";
  auto tiny = against_reference(scene, [](ir::Module& m) {
    m.plan.march.normal_step = 1e-6;
    m.plan.march.normal_step_floor = 1e-12;  // as render.normal_step in the scene sets it
  });
  auto tiny_double = against_reference(scene, [](ir::Module& m) {
    m.plan.march.normal_step = 1e-6;
    m.plan.march.normal_step_floor = 1e-12;
    m.plan.march.precision = ir::Precision::Double;
  });
  auto footprint = against_reference(scene, [](ir::Module&) {});
  EXPECT_GT(tiny.normal_error_deg_median, 10.0);
  EXPECT_LT(tiny_double.normal_error_deg_median, 2.0);
  EXPECT_LT(footprint.normal_error_deg_median, 2.0);
  EXPECT_EQ(tiny.holes_pct, 0.0);  // the surface is found all the same
}

// Float at a deep Mandelbulb zoom: the camera 0.05 from a surface point
// (|p| ~ 0.87, where a float resolves 6e-8), the field of view narrowed so a
// pixel's footprint is 7e-6 (shallow) or 7e-9 (deep). With footprint-scaled
// normals (render.normal_step given, so no 1e-6 floor) float is as good as
// double when shallow and breaks when deep; double holds.
TEST(Stability, DeepMandelbulbZoomNeedsDouble) {
  auto scene = [](double fov) {
    return fmt::format("camera: {{position: [0, -0.89940840, 0.20755579], target: [0, -0.85068884, 0.19631281], "
                       "up: [0, 0, 1], fov: {}}}\nrender: {{normal_step: 0.5}}\n{}"
                       "scene: {{mandelbulb: {{power: 8, iterations: 10, bailout: 2}}}}\n",
                       fov, kLight);
  };
  auto as_double = [](ir::Module& m) { m.plan.march.precision = ir::Precision::Double; };
  auto shallow_f = against_reference(scene(0.45), [](ir::Module&) {});
  auto shallow_d = against_reference(scene(0.45), as_double);
  auto deep_f = against_reference(scene(0.00045), [](ir::Module&) {});
  auto deep_d = against_reference(scene(0.00045), as_double);
  EXPECT_LT(shallow_f.normal_error_deg_median, shallow_d.normal_error_deg_median + 1.0);
  EXPECT_GT(deep_f.normal_error_deg_median, 20.0);
  EXPECT_LT(deep_d.normal_error_deg_median, 2.0);
  EXPECT_LT(deep_f.ssim, 0.5);
  EXPECT_GT(deep_d.ssim, 0.9);
}

// A floor seen at a grazing angle: rays near the horizon creep towards it
// in ever smaller steps; with too few they run out and leave holes, which
// more steps fill.
TEST(Stability, TooFewStepsLeaveHolesAtGrazingAngles) {
  const std::string scene = std::string("camera: {position: [0, -6, 0.25], target: [0, 0, 0], up: [0, 0, 1], fov: 30}\n") + kLight +
                            "render: {max_distance: 30}\n"
                            "scene: {box: {size: [30, 30, 0.2]}, translate: [0, 8, -0.1]}\n";
  auto few = against_reference(scene, [](ir::Module& m) { m.plan.march.max_steps = 24; });
  auto enough = against_reference(scene, [](ir::Module& m) { m.plan.march.max_steps = 1024; });
  EXPECT_GT(few.holes_pct, 2.0);
  EXPECT_LT(enough.holes_pct, 0.1 * few.holes_pct);
}

// The reference's hit epsilon (0.01 px) is converged on the Mandelbulb: a
// 10x smaller one changes the hit mask and the depth far less than the
// render's 0.5 px does (docs/accuracy.md, the convergence check).
TEST(Reference, HitEpsilonConvergesOnTheMandelbulb) {
  const std::string scene = std::string("camera: {position: [0, -2.6, 0.6], target: [0, 0, 0], up: [0, 0, 1], fov: 45}\n") +
                            kLight + "scene: {mandelbulb: {power: 8, iterations: 10, bailout: 2}}\n";
  auto ref_at = [](double eps) { return [eps](ir::Module& m) { ir::make_reference(m.plan.march, eps); }; };
  auto tenth = against_reference(scene, ref_at(0.1 * ir::kReferenceHitEpsilon));
  auto coarse = against_reference(scene, ref_at(50 * ir::kReferenceHitEpsilon));  // 0.5 px, in double
  EXPECT_LT(tenth.hit_mask_disagreement_pct, 0.5);
  EXPECT_GT(coarse.hit_mask_disagreement_pct, 4 * tenth.hit_mask_disagreement_pct);
  EXPECT_LT(tenth.depth_rel_error_median, 0.2 * coarse.depth_rel_error_median);
}

}  // namespace
}  // namespace sdfc
