// Object sets in images (sdfc/ir/object_set.hpp): a scene renders the same
// image with its union as data as with it unrolled, its camera rays' cones
// hit what the whole union hits, and its hits' shading (path-traced too) and
// occlusion probes, which ask the set for less, get the values of a whole
// walk. On PoCL.
#include <gtest/gtest.h>

#include <functional>
#include <regex>
#include <string>
#include <utility>

#include "object_set_scenes.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc_test_support.hpp"
#include "sdfrt/renderer.hpp"

namespace sdfc {
namespace {

using test::Case;
using test::cases;
using test::unrolled;

// Camera rays march in their packet's cone (os_cone); `cones` false gives
// them none, as every other ray, so the set's distance is the whole union's.
// `edit` changes the kernel's source first.
sdfrt::FloatImage render(const ir::Module& m, const codegen::EmitOptions& opt = {16}, bool cones = true,
                         const std::function<std::string(const std::string&)>& edit = {}) {
  codegen::EmittedKernel k = codegen::emit_opencl(m, opt);
  if (!cones) k.source = std::regex_replace(k.source, std::regex(R"(os_camera_cone\([^;]*\);)"), "os_cone_none();");
  if (edit) k.source = edit(k.source);
  sdfrt::Renderer r(test::device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, "", k.scene_data});
  const int w = m.plan.march.width, h = m.plan.march.height;
  return r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h);
}

// Runs `check` on the case's set at packet widths 1, 16 and 64 (or those
// given), with the material, normal and hit planes.
using Check = std::function<void(const ir::Module&, const codegen::EmitOptions&)>;
void each_width(const Case& c, const Check& check, std::initializer_list<int> widths = {1, 16, 64}) {
  SCOPED_TRACE(c.name);
  ir::Module set = test::compile_text(c.yaml);
  for (int width : widths) {
    SCOPED_TRACE(width);
    codegen::EmitOptions opt{width};
    opt.aovs = true;
    check(set, opt);
  }
}

// The kernel source with the first `from` replaced by `to` (which must be there).
std::string replace(std::string k, const std::string& from, const std::string& to) {
  const size_t at = k.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? k : k.replace(at, from.size(), to);
}
// The hits shaded by walking the set, not from the packet's list.
std::string walked(const std::string& k) { return replace(k, "os_cone_shading(cone)", "os_cone_none()"); }

// How many values (of every plane) differ between two renders of one size.
size_t differing(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b) {
  EXPECT_EQ(a.data.size(), b.data.size());
  size_t n = 0;
  for (size_t i = 0; i < std::min(a.data.size(), b.data.size()); ++i) n += a.data[i] != b.data[i];
  return n;
}

// Without cones the set renders the unrolled union's image bit for bit,
// though its normals' taps cull the walk by the hit's distance
// (normal_tetrahedral_below) and the unrolled union's evaluate everything.
TEST(ObjectSetRender, SameImageAsTheUnrolledUnion) {
  for (const Case& c : cases()) {
    ir::Module code = unrolled(c.yaml);
    each_width(c, [&](const ir::Module& set, const codegen::EmitOptions& opt) {
      ASSERT_EQ(codegen::emit_opencl(set, opt).source.find("normal_tetrahedral_below(TIME_ARG pos") != std::string::npos,
                c.seen_whole);
      sdfrt::FloatImage a = render(set, opt, false), b = render(code, opt);
      size_t hits = 0;
      for (float v : a.plane(a.plane_index("hit"))) hits += v > 0;
      EXPECT_EQ(differing(a, b), 0u);
      if (c.name != "far_apart") {
        EXPECT_GT(hits, 0u);  // the objects are in view
      }
    });
  }
}

// In its cone a camera ray steps past the items beside its path, so it
// lands elsewhere within the hit band, but it hits what the whole union's
// march hits (the march without cones, which renders the unrolled union's
// image above): the two hit masks differ only on silhouettes (a pixel whose
// neighbour's hit differs without cones), never inside an object, at every
// packet width (one lane: the thinnest cone). The march measures the cone's
// items from a list (os_list) where it holds them all, and walks the
// hierarchy where not ("coincident": all 100 items in every cone).
Check hits_as_the_whole_union(const Case& c) {
  return [&c](const ir::Module& set, const codegen::EmitOptions& opt) {
    const std::string k = codegen::emit_opencl(set, opt).source;
    ASSERT_EQ(k.find("= os_camera_cone(") != std::string::npos, c.seen_whole);
    ASSERT_EQ(k.find("os_list_gather(&list, cone, ") != std::string::npos, c.seen_whole);
    sdfrt::FloatImage a = render(set, opt), b = render(set, opt, false);
    auto ha = a.plane(a.plane_index("hit")), hb = b.plane(b.plane_index("hit"));
    const int w = a.width, h = a.height;
    auto edge = [&](int x, int y) {
      for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        int u = x + dx, v = y + dy;
        if (u >= 0 && v >= 0 && u < w && v < h && (hb[size_t(v * w + u)] > 0) != (hb[size_t(y * w + x)] > 0)) return true;
      }
      return false;
    };
    size_t silhouette = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if ((ha[size_t(y * w + x)] > 0) != (hb[size_t(y * w + x)] > 0)) {
          EXPECT_TRUE(edge(x, y)) << "pixel " << x << ", " << y;
          ++silhouette;
        }
    EXPECT_LT(silhouette, size_t(w * h) / 100);
  };
}
TEST(ObjectSetRender, CameraConesHitWhatTheWholeUnionHits) {
  for (const Case& c : cases()) each_width(c, hits_as_the_whole_union(c));
}

// The hits' material and normal taps read the packet's list (os_union_shade)
// where it holds every item that could be nearest, and walk the set
// elsewhere: the same values as the walk's, bit for bit, at every width.
// A list of the camera's cone alone, made to shade, answers less often
// (none beside the packet's edges), still with the walk's values; without
// its check it gives others.
TEST(ObjectSetRender, HitsShadedFromTheListAsFromTheWalk) {
  auto narrow = [&](const std::string& k) {
    return replace(replace(k, "pixel_angle * 0.8660254f);", "0.0f);"), "if (c.cos_w == c.cos_a) c.list = 0;", "");
  };
  auto unchecked = [&](const std::string& k) {
    return replace(narrow(k), "if (M_ANY(live & (best > depth))) return false;", "");
  };
  size_t differ_unchecked = 0;
  for (const Case& c : cases()) {
    if (!c.seen_whole) continue;
    each_width(c, [&](const ir::Module& set, const codegen::EmitOptions& opt) {
      ASSERT_NE(codegen::emit_opencl(set, opt).source.find("= os_cone_shading(cone);"), std::string::npos);
      sdfrt::FloatImage want = render(set, opt, true, walked);
      EXPECT_EQ(differing(render(set, opt), want), 0u);
      EXPECT_EQ(differing(render(set, opt, true, narrow), want), 0u);
      differ_unchecked += differing(render(set, opt, true, unchecked), want);
    });
  }
  EXPECT_GT(differ_unchecked, 0u);
}

// The list's loops skip items by the live lanes' nearest and farthest
// (lanes_reduce, a tree over the packet's halves that differs by width):
// at the other packet widths too, the camera rays hit what the whole union
// hits and the hits are shaded with the walk's values.
TEST(ObjectSetRender, ListsReadTheirLanesAtEveryWidth) {
  for (const Case& c : cases()) {
    if (c.name != "flat" && c.name != "groups") continue;
    each_width(c, hits_as_the_whole_union(c), {2, 4, 8, 32});
    each_width(c, [](const ir::Module& set, const codegen::EmitOptions& opt) {
      EXPECT_EQ(differing(render(set, opt), render(set, opt, true, walked)), 0u);
    }, {2, 4, 8, 32});
  }
}

// An occlusion probe h above the hit counts only where the distance is
// below h, so it walks the set with h as its bound (scene_dist_probe), for
// the hits' lanes only: the image of the whole walk, bit for bit. A bound
// of h / 2 gives another.
TEST(ObjectSetRender, OcclusionProbesBoundedByTheirHeight) {
  const std::string bounded = "scene_dist_below(TIME_ARG p, below, live, os_cone_none())";
  auto edit = [&](const std::string& to) {
    return [&bounded, to](const std::string& k) { return replace(k, bounded, to); };
  };
  size_t differ_halved = 0;
  for (const Case& c : cases()) {
    if (!c.seen_whole || c.name == "far_apart") continue;
    SCOPED_TRACE(c.name);
    ir::Module set = test::compile_text(c.yaml, "test.yaml",
                                        {"effects.ambient_occlusion.method=normal_samples", "effects.ambient_occlusion.distance=0.6"});
    for (int width : {1, 16, 64}) {
      SCOPED_TRACE(width);
      codegen::EmitOptions opt{width};
      opt.aovs = true;
      ASSERT_NE(codegen::emit_opencl(set, opt).source.find("ao_normal_samples(TIME_ARG pos, n, "), std::string::npos);
      sdfrt::FloatImage want = render(set, opt, true, edit("scene_dist(TIME_ARG p)"));
      EXPECT_EQ(differing(render(set, opt), want), 0u);
      differ_halved += differing(render(set, opt, true, edit("scene_dist_below(TIME_ARG p, 0.5f * below, live, os_cone_none())")), want);
    }
  }
  EXPECT_GT(differ_halved, 0u);
}

// The path integrator's hits take their material first and bound their
// normals' taps by its distance, as the direct integrator's do: the image
// of the unrolled union, bit for bit. Taps bounded by less give another. A
// set walked whole (turned) keeps the unbounded taps.
TEST(ObjectSetRender, PathTracedHitsBoundTheirNormalsWithTheSameImage) {
  const std::string head = "render: {width: 96, height: 64}", bound = "reach * K(1.001f)";
  size_t differ_tight = 0;
  for (const Case& c : cases()) {
    if (c.name != "flat" && c.name != "groups" && c.name != "turned") continue;
    SCOPED_TRACE(c.name);
    std::string yaml = c.yaml;
    yaml.replace(yaml.find(head), head.size(), "render: {width: 96, height: 64, integrator: path, samples: 2, max_bounces: 2}");
    ir::Module set = test::compile_text(yaml), code = unrolled(yaml);
    for (int width : {1, 64}) {
      SCOPED_TRACE(width);
      codegen::EmitOptions opt{width};
      opt.aovs = true;
      const std::string k = codegen::emit_opencl(set, opt).source;
      ASSERT_EQ(k.find("normal_tetrahedral_below(TIME_ARG pos, h, d_hit, hit, os_cone_none());") != std::string::npos,
                c.seen_whole);
      if (!c.seen_whole) continue;
      const sdfrt::FloatImage want = render(code, opt);
      EXPECT_EQ(differing(render(set, opt), want), 0u);
      differ_tight += differing(render(set, opt, true, [&](const std::string& s) {
                                  return replace(s, bound, "reach * K(0.25f)");
                                }),
                                want);
    }
  }
  EXPECT_GT(differ_tight, 0u);
}

}  // namespace
}  // namespace sdfc
