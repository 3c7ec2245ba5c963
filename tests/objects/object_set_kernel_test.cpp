// Object sets in the kernel: where the camera rays get a cone, where the
// normals bound their taps, the source's size, and which walks are masked.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>
#include <vector>

#include "object_set_scenes.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/object_set.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc {
namespace {

using test::scene;

// Only camera rays through a pinhole whose march feeds nothing but the hit
// get a cone: depth of field moves the rays' origins; glow, occlusion from
// the step count and bisection read the march itself; the path integrator
// has its own.
TEST(ObjectSetKernel, CameraConesOnlyWhereTheMarchFeedsOnlyTheHit) {
  auto cones = [](const std::vector<std::string>& sets) {
    return codegen::emit_opencl(test::compile_text(scene(100), "test.yaml", sets), {16}).source.find("= os_camera_cone(") !=
           std::string::npos;
  };
  EXPECT_TRUE(cones({}));
  EXPECT_TRUE(cones({"effects.ambient_occlusion.method=normal_samples"}));
  EXPECT_FALSE(cones({"camera.aperture=0.1"}));
  EXPECT_FALSE(cones({"effects.glow.strength=1"}));
  EXPECT_FALSE(cones({"effects.ambient_occlusion.method=step_count"}));
  EXPECT_FALSE(cones({"render.refine=bisection"}));
  EXPECT_FALSE(cones({"render.integrator=path"}));
}

TEST(ObjectSetKernel, SourceSizeDoesNotGrowWithTheCount) {
  size_t small = codegen::emit_opencl(test::compile_text(scene(100)), {16}).source.size();
  codegen::EmittedKernel big = codegen::emit_opencl(test::compile_text(scene(5000)), {16});
  EXPECT_LT(big.source.size(), small + 200);  // a few digits more in the comment and the call
  EXPECT_GT(big.scene_data.size(), 5000u * ir::object_set::kPrimFloats);
}

// In the marching loops a stopped lane's value is thrown away, so the walk
// is given the loop's mask of lanes still marching; the hits' shading gives
// it the hits (and the packet's list, os_cone_shading); every other use of
// the scene's distance needs every lane's value.
TEST(ObjectSetKernel, TheWalkOpensBoxesForTheLanesWhoseValuesAreUsed) {
  const std::string k = codegen::emit_opencl(test::compile_text(scene(100)), {16}).source;
  auto body = [&](const std::string& signature) {
    size_t at = k.find(signature);
    EXPECT_NE(at, std::string::npos) << signature;
    return at == std::string::npos ? std::string() : k.substr(at, k.find("\n}\n", at) - at);
  };
  const std::string marching = body("real scene_dist_cone(TIME_PARAM vec3 p, mask live, const os_cone cone)");
  EXPECT_NE(marching.find("os_union("), std::string::npos);
  EXPECT_NE(marching.find(", live, cone, &"), std::string::npos);
  EXPECT_NE(k.find("{ return scene_dist_cone(TIME_ARG p, live, os_cone_none()); }"), std::string::npos);
  const std::string with_material = body("real scene_dist_mat_hit(TIME_PARAM vec3 p, mask live, const os_cone cone, real* mat)");
  EXPECT_NE(with_material.find(", live, cone, &"), std::string::npos);
  EXPECT_NE(k.find("{ return scene_dist_mat_hit(TIME_ARG p, M_TRUE, os_cone_none(), mat); }"), std::string::npos);
  const std::string called = body("real scene_dist_below(TIME_PARAM vec3 p, real above, mask live, const os_cone cone)");
  EXPECT_NE(called.find(", above, live, cone, &"), std::string::npos);
  EXPECT_NE(k.find("{ return scene_dist_below(TIME_ARG p, K(1e30f), M_TRUE, os_cone_none()); }"), std::string::npos);
  EXPECT_NE(k.find("const os_cone shade = os_cone_shading(cone);"), std::string::npos);
  EXPECT_NE(k.find("const real d_hit = scene_dist_mat_hit(TIME_ARG pos, hit, shade, &id);"), std::string::npos);
}

// The camera rays' cone reaches a set only through unions, bounding boxes
// and materials (a set turned or moved as one sees other points than the
// rays); its items are listed once per packet only where one set has them.
TEST(ObjectSetKernel, CameraListsWhereOneSetSeesTheWorld) {
  auto source = [](const std::string& yaml) { return codegen::emit_opencl(test::compile_text(yaml), {16}).source; };
  std::string moved;
  for (int i = 0; i < 30; ++i) moved += fmt::format("        - sphere: {{radius: 0.2}}\n          translate: [{}, {}, 0]\n", i % 6, i / 6);
  const std::string one = source(scene(100));
  EXPECT_NE(one.find("os_list_gather(&list, cone, scene_data + 0, "), std::string::npos);
  EXPECT_NE(one.find("cone.list = &list;"), std::string::npos);
  const std::string two = source(scene(100, 1, "    - union:\n" + moved + "      translate: [0, 0, 3]\n"));
  EXPECT_NE(two.find("= os_camera_cone("), std::string::npos);  // the first set sees the world
  EXPECT_EQ(two.find("os_list_gather(&list"), std::string::npos);
  EXPECT_NE(two.find("os_camera_cone(ro, rd, pixel_angle * 0.5f, 0.0f);"), std::string::npos);  // no list to widen
  const std::string away = source(std::string(test::kHead) + "    - plane: {normal: [0, 0, 1], offset: 0}\n    - union:\n" + moved +
                                  "      translate: [0, 0, 3]\n");
  EXPECT_EQ(away.find("= os_camera_cone("), std::string::npos);
}

// The normals' taps cull the set's walk by the distance at the hit plus
// their reach only where the scene's distance is 1-Lipschitz: the set alone
// or beside exact shapes, never beside a fractal's estimate or a shape
// divided by its Lipschitz constant (a twist). The image is the same either
// way (ObjectSetRender.SameImageAsTheUnrolledUnion).
TEST(ObjectSetKernel, NormalsBoundTheirTapsOnlyWhereTheDistanceIsOneLipschitz) {
  auto source = [](const std::string& extra, const std::vector<std::string>& sets = {}) {
    return codegen::emit_opencl(test::compile_text(scene(100, 1, extra), "test.yaml", sets), {16}).source;
  };
  auto bounded = [](const std::string& k) {
    return k.find("= normal_tetrahedral_below(TIME_ARG pos, h, d_hit, hit, shade);") != std::string::npos;
  };
  const std::string alone = source("");
  EXPECT_TRUE(bounded(alone));
  EXPECT_NE(alone.find("const real d_hit = scene_dist_mat_hit(TIME_ARG pos, hit, shade, &id);"), std::string::npos);
  // the list's cone is wider by the farthest tap's angle: sqrt(3) h, or h for central normals
  EXPECT_NE(alone.find("os_camera_cone(ro, rd, pixel_angle * 0.5f, pixel_angle * 0.8660254f);"), std::string::npos);
  EXPECT_TRUE(bounded(source("    - plane: {normal: [0, 0, 1], offset: -1}\n")));
  const std::string central = source("", {"render.normals=central"});
  EXPECT_NE(central.find("= normal_central_below(TIME_ARG pos, h, d_hit, hit, shade);"), std::string::npos);
  EXPECT_NE(central.find("os_camera_cone(ro, rd, pixel_angle * 0.5f, pixel_angle * 0.5f);"), std::string::npos);
  EXPECT_FALSE(bounded(source("    - mandelbulb: {power: 8}\n      translate: [0, 0, 6]\n")));
  EXPECT_FALSE(bounded(source("    - torus: {major_radius: 1, minor_radius: 0.3}\n      twist: {rate: 2}\n")));
}

}  // namespace
}  // namespace sdfc
