// camera.fit and camera.fov_axis, rendered on the device: a fitted view
// holds the whole object (no hit pixel on the image border) and fills most
// of the frame (at least half: a fractal's bounds are a little loose, and
// a box's corners reach past the shape inside); the fov spans the side fov_axis names at any image size.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "e2e_support.hpp"
#include "sdfc/codegen/camera_view.hpp"

namespace sdfc::e2e {
namespace {

struct HitBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  bool any() const { return x1 >= 0; }
};

HitBox hit_box(const sdfrt::FloatImage& img) {
  int k = img.plane_index("depth");  // -1 where the ray missed
  EXPECT_GE(k, 0);
  HitBox b;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.plane(k)[size_t(y) * img.width + x] > 0.0f)
        b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
  return b;
}

HitBox render_hits(const std::string& yaml, int w, int h) {
  ir::Module m = test::compile_text(yaml, "fit.yaml", {"render.width=" + std::to_string(w), "render.height=" + std::to_string(h)});
  return hit_box(render(m, 16));
}

struct FitCase {
  const char* name;
  const char* camera;
  const char* scene;
};

class CameraFit : public ::testing::TestWithParam<FitCase> {};

TEST_P(CameraFit, HoldsTheWholeObjectAndFillsMostOfTheFrame) {
  const FitCase& c = GetParam();
  for (auto [w, h] : {std::pair{192, 108}, std::pair{108, 192}, std::pair{128, 128}}) {
    std::string yaml = std::string("camera: ") + c.camera + "\nscene: " + c.scene + "\n";
    HitBox b = render_hits(yaml, w, h);
    ASSERT_TRUE(b.any()) << c.name << " at " << w << "x" << h;
    EXPECT_GT(b.x0, 0) << c.name << " touches the left border at " << w << "x" << h;
    EXPECT_GT(b.y0, 0) << c.name << " touches the top border at " << w << "x" << h;
    EXPECT_LT(b.x1, w - 1) << c.name << " touches the right border at " << w << "x" << h;
    EXPECT_LT(b.y1, h - 1) << c.name << " touches the bottom border at " << w << "x" << h;
    double fill = std::max(double(b.x1 - b.x0 + 1) / w, double(b.y1 - b.y0 + 1) / h);
    EXPECT_GT(fill, 0.5) << c.name << " fills too little of " << w << "x" << h;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CameraFit,
    ::testing::Values(
        FitCase{"SphereFarAway", "{position: [30, -40, 10], target: [5, 3, 0], fit: true}",
                "{sphere: {radius: 0.5}, translate: [5, 3, 0]}"},
        FitCase{"Mandelbox", "{position: [1, -2, 0.8], target: [0, 0, 0], fit: true, fov: 40}", "{mandelbox: {scale: -1.5}}"},
        FitCase{"KifsFromADirection", "{direction: [-1, 1, -0.5], fit: true}", "{kifs: {}}"},
        FitCase{"TwoShapesApart", "{position: [0, -3, 1], target: [0, 0, 0], fit: true, fov_axis: auto}",
                "{union: [{mandelbulb: {}, translate: [-2, 0, 0]}, {box: {size: [1, 1, 3]}, translate: [2, 1, 0]}]}"},
        FitCase{"Menger", "{position: [3, -2, 2], target: [0, 0, 0], fit: true, fov: 60}", "{menger: {}}"}),
    [](const auto& info) { return std::string(info.param.name); });

// The fraction of the image's width (or height) a sphere in the middle spans.
double span(const std::string& axis, int w, int h, bool across) {
  HitBox b = render_hits("camera: {position: [0, -5, 0], target: [0, 0, 0], fov: 30, fov_axis: " + axis +
                             "}\nscene: {sphere: {radius: 0.5}}\n",
                         w, h);
  EXPECT_TRUE(b.any());
  return across ? double(b.x1 - b.x0 + 1) / w : double(b.y1 - b.y0 + 1) / h;
}

TEST(FovAxis, KeepsTheNamedSideAtEveryAspect) {
  // vertical: the sphere spans the same share of the height at 16:9 and 21:9.
  EXPECT_NEAR(span("vertical", 160, 90, false), span("vertical", 210, 90, false), 0.03);
  // horizontal: the same share of the width.
  EXPECT_NEAR(span("horizontal", 160, 90, true), span("horizontal", 210, 90, true), 0.03);
  // auto: the longer side, so landscape keeps the width, portrait the height.
  EXPECT_NEAR(span("auto", 160, 90, true), span("horizontal", 160, 90, true), 0.02);
  EXPECT_NEAR(span("auto", 90, 160, false), span("vertical", 90, 160, false), 0.02);
  // The same fov on the other side: horizontal at 16:9 sees less than vertical.
  EXPECT_GT(span("horizontal", 160, 90, true), span("vertical", 160, 90, true) * 1.3);
}

TEST(FovAxis, TangentsFollowTheAxis) {
  ir::Camera c;
  c.fov_degrees = 90;
  c.fov_axis = ir::Camera::FovAxis::Horizontal;
  auto t = codegen::fov_tangents(c, 200, 100);
  EXPECT_NEAR(t[0], 1.0, 1e-12);
  EXPECT_NEAR(t[1], 0.5, 1e-12);
  c.fov_axis = ir::Camera::FovAxis::Auto;
  t = codegen::fov_tangents(c, 100, 200);
  EXPECT_NEAR(t[1], 1.0, 1e-12);
  EXPECT_NEAR(t[0], 0.5, 1e-12);
}

}  // namespace
}  // namespace sdfc::e2e
