// An unlocked value is read from the frame block: the kernel built once with
// it unlocked renders, for any value in its range, the image the kernel baked
// with that value renders; and its text differs from the baked kernel's only
// in how the value arrives.
#include <gtest/gtest.h>
#include <sdfrt/renderer.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <sstream>

#include "sdfc/compile.hpp"
#include "sdfc/source/yaml_loader.hpp"
#include "sdfc_test_support.hpp"
#include "unlock_support.hpp"

namespace sdfc::test {

Unlocked compile_unlocked(const std::string& yaml, const std::vector<std::string>& unlocks) {
  SourceValue doc = load_yaml_text(yaml, "unlock.yaml");
  std::vector<UnlockRequest> rq;
  for (const auto& u : unlocks) rq.push_back(parse_unlock(u));
  Unlocked u;
  u.slots = mark_unlocked(doc, rq);
  u.module = build_module(doc, "unlock.yaml");
  return u;
}

sdfrt::FloatImage render_with(const ir::Module& m, const std::vector<float>& values) {
  codegen::EmittedKernel k = codegen::emit_opencl(m, {kSimd, false});
  EXPECT_EQ(k.frame_floats, codegen::kFrameFloats + int(values.size()));
  std::vector<float> frame = codegen::frame_params(m.plan, kWidth, kHeight);
  frame.insert(frame.end(), values.begin(), values.end());
  sdfrt::Renderer r(device(), sdfrt::KernelSpec{.source = k.source,
                                                .entry = k.entry,
                                                .simd_width = k.simd_width,
                                                .packet_rows = k.packet_rows,
                                                .planes = k.planes});
  return r.render(frame, kWidth, kHeight);
}

double max_difference(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) worst = std::max(worst, double(std::fabs(a.at(c, x, y) - b.at(c, x, y))));
  return worst;
}

double share_apart(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  int apart = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool off = false;
      for (int c = 0; c < 3; ++c) off = off || std::fabs(a.at(c, x, y) - b.at(c, x, y)) > 1.0 / 255;
      apart += off;
    }
  return double(apart) / (double(a.width) * a.height);
}

namespace {

// An unlocked value's bounds hold for its whole range, so the march is clipped
// to a larger box and its steps land elsewhere: where a ray grazes a surface
// the hit moves a little. At most this share of pixels may differ by more
// than 1/255 (a range of one value renders within 1/255 everywhere).
constexpr double kGrazingShare = 0.05;

// A sphere beside a box, a point light and a sun: the values the panel's sliders move.
std::string scene(double radius, double intensity, double shift) {
  std::ostringstream s;
  s << "camera: {position: [0, -6, 2], target: [0, 0, 0], up: [0, 0, 1], fov: 40}\n"
       "lights:\n"
       "  - point: {position: [2, -3, 3], color: [1, 0.9, 0.8], intensity: " << intensity << "}\n"
       "  - directional: {direction: [-0.3, 0.5, -0.8], intensity: 0.6}\n"
       "scene:\n"
       "  union:\n"
       "    - sphere: {radius: " << radius << "}\n"
       "      translate: [" << shift << ", 0, 0]\n"
       "    - box: {size: [1, 1, 1]}\n"
       "      translate: [1.5, 0, 0]\n";
  return s.str();
}

TEST(Unlock, SphereRadiusRendersAsTheBakedKernel) {
  Unlocked point = compile_unlocked(scene(0.8, 6, -1), {"scene.union[0].sphere.radius=0.8:0.8"});
  EXPECT_LE(max_difference(render_with(point.module, {0.8f}), render_with(compile_unlocked(scene(0.8, 6, -1), {}).module, {})),
            1.0 / 255);
  Unlocked u = compile_unlocked(scene(0.8, 6, -1), {"scene.union[0].sphere.radius=0.4:1.6"});
  ASSERT_EQ(u.slots.size(), 1u);
  EXPECT_EQ(u.slots[0]->value, 0.8);
  sdfrt::FloatImage first;
  for (double r : {0.8, 0.5, 1.3}) {
    sdfrt::FloatImage live = render_with(u.module, {float(r)});
    sdfrt::FloatImage baked = render_with(compile_unlocked(scene(r, 6, -1), {}).module, {});
    EXPECT_LE(share_apart(live, baked), kGrazingShare) << "radius " << r;
    std::cout << "radius " << r << ": " << 100 * share_apart(live, baked) << "% of pixels more than 1/255 apart\n";
    if (r == 0.8) first = live;
    else EXPECT_GT(max_difference(live, first), 0.1) << "radius " << r << " changes nothing";
  }
}

TEST(Unlock, LightIntensityAndTranslationRenderAsTheBakedKernel) {
  // Default ranges (from what the readers accept) and two slots at once.
  Unlocked u = compile_unlocked(scene(0.8, 6, -1), {"lights[0].point.intensity", "scene.union.0.translate.0"});
  ASSERT_EQ(u.slots.size(), 2u);
  EXPECT_LT(u.slots[0]->lo, 6);
  EXPECT_GE(u.slots[0]->lo, 0);  // an intensity is at least 0
  EXPECT_GT(u.slots[1]->hi, -1);
  for (auto [i, x] : {std::pair{3.0, -1.4}, std::pair{10.0, -0.5}}) {
    sdfrt::FloatImage live = render_with(u.module, {float(i), float(x)});
    sdfrt::FloatImage baked = render_with(compile_unlocked(scene(0.8, i, x), {}).module, {});
    EXPECT_LE(share_apart(live, baked), kGrazingShare) << "intensity " << i << ", x " << x;
  }
}

std::multiset<std::string> lines_of(const std::string& s) {
  std::multiset<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.insert(l);
  return out;
}

std::vector<std::string> minus(const std::multiset<std::string>& a, const std::multiset<std::string>& b) {
  std::vector<std::string> out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

TEST(Unlock, KernelTextDiffersOnlyWhereTheValueArrives) {
  // A range of one value keeps every bound as the baked kernel's, so only the
  // value's own uses and the argument that carries it may differ.
  Unlocked u = compile_unlocked(scene(0.8, 6, -1), {"scene.union[0].sphere.radius=0.8:0.8"});
  const std::string live = codegen::emit_opencl(u.module, {kSimd, false}).source;
  const std::string baked = codegen::emit_opencl(compile_unlocked(scene(0.8, 6, -1), {}).module, {kSimd, false}).source;
  EXPECT_NE(live.find("sd_sphere(p0, ((scalar)unlocked[0]))"), std::string::npos) << live;
  const auto only_live = minus(lines_of(live), lines_of(baked));
  const auto only_baked = minus(lines_of(baked), lines_of(live));
  EXPECT_FALSE(only_live.empty());
  for (const auto& l : only_live)
    EXPECT_TRUE(l.find("unlocked") != std::string::npos || l.find("time") != std::string::npos) << l;
  for (const auto& l : only_baked)
    EXPECT_TRUE(l.find("0.8f") != std::string::npos || l.find("TIME_") != std::string::npos ||
                l.find("static") != std::string::npos)
        << l;
}

}  // namespace
}  // namespace sdfc::test
