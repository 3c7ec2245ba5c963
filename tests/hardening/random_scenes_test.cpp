// What `check` accepts builds: seeded random valid scenes (every node kind,
// modifier, domain operation, effect and light) are compiled, built and
// rendered at 8x8. None may fail to build, throw anything but a scene error
// or give a NaN; SIMD width 1 must give the same pixels as 16 (within half
// an 8-bit step; every 4th scene), and double precision must build too
// (every 8th). SDFC_RANDOM_SCENES=N (default 200) and
// SDFC_RANDOM_SEED=S (default 1) choose the seeds S .. S+N-1; the shards
// split them so ctest runs them in parallel. bench/random_scenes runs
// thousands.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <sdfrt/errors.hpp>
#include <sdfrt/renderer.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "random_scene.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc_test_support.hpp"

namespace sdfc::test {
namespace {

constexpr int kShards = 8;

long env_or(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 10) : fallback;
}

sdfrt::FloatImage render(const ir::Module& m, int simd_width) {
  codegen::EmitOptions eo;
  eo.simd_width = simd_width;
  codegen::EmittedKernel k = codegen::emit_opencl(m, eo);
  sdfrt::KernelSpec spec{.source = k.source,
                         .entry = k.entry,
                         .simd_width = k.simd_width,
                         .packet_rows = k.packet_rows,
                         .planes = k.planes};
  sdfrt::Renderer r(device(), spec);
  const int w = m.plan.march.width, h = m.plan.march.height;
  return r.render(codegen::frame_params(m.plan, w, h, 0.0), w, h, sdfrt::RenderOptions{});
}

bool finite_rgb(const sdfrt::FloatImage& img) {
  for (size_t i = 0; i < 3 * img.plane_size(); ++i)
    if (!std::isfinite(img.data[i])) return false;
  return true;
}

double fraction_differing(const sdfrt::FloatImage& a, const sdfrt::FloatImage& b, float tolerance) {
  size_t n = 0;
  for (size_t i = 0; i < 3 * a.plane_size(); ++i) n += std::fabs(a.data[i] - b.data[i]) > tolerance;
  return double(n) / double(3 * a.plane_size());
}

class RandomScenes : public ::testing::TestWithParam<int> {};

TEST_P(RandomScenes, EveryAcceptedSceneBuildsAndRendersAlikeAtEveryWidth) {
  const long count = env_or("SDFC_RANDOM_SCENES", 200), first = env_or("SDFC_RANDOM_SEED", 1);
  int accepted = 0, refused = 0, build_failures = 0, crashes = 0, width_checks = 0, width_mismatches = 0,
      double_builds = 0, nonfinite = 0;
  double worst_precision = 0;
  std::map<std::string, int> refusals;
  int done = 0;
  for (long seed = first + GetParam(); seed < first + count; seed += kShards) {
    if (++done % 25 == 0) {  // long runs (bench/random_scenes) show their counts as they go
      std::printf("random scenes so far (shard %d): %d accepted, %d refused, %d build failures, %d other errors, "
                  "%d NaN images, %d of %d widths identical\n",
                  GetParam(), accepted, refused, build_failures, crashes, nonfinite, width_checks - width_mismatches,
                  width_checks);
      std::fflush(stdout);
    }
    std::string yaml = random_scene(std::uint64_t(seed));
    std::string stage = "compile";
    try {
      ir::Module m = compile_text(yaml, fmt::format("random_{}.yaml", seed));
      ++accepted;
      stage = "build at width 16";
      sdfrt::FloatImage wide = render(m, 16);
      if (!finite_rgb(wide)) ++nonfinite, ADD_FAILURE() << "NaN/Inf pixel, seed " << seed << "\n" << yaml;
      if ((seed / kShards) % 4 == 0) {
        stage = "build at width 1";
        ++width_checks;
        // Vector and scalar maths may differ in the last bits: equal within
        // half a step of an 8-bit image (what the PNG comparison saw).
        if (fraction_differing(wide, render(m, 1), 1.0f / 512) > 0)
          ++width_mismatches, ADD_FAILURE() << "width 1 differs from 16, seed " << seed << "\n" << yaml;
      }
      if ((seed / kShards) % 8 == 1) {
        stage = "build in double precision";
        ir::Module d = compile_text(yaml, "random.yaml", {"render.precision=double"});
        worst_precision = std::max(worst_precision, fraction_differing(wide, render(d, 16), 0.05f));
        ++double_builds;
      }
    } catch (const SceneError& e) {
      if (stage != "compile") throw;
      ++refused;
      std::string what = e.what();
      what = what.substr(what.find("error: ") + 7);
      refusals[what.substr(0, what.find_first_of("(0123456789'"))] += 1;
    } catch (const sdfrt::BuildError& e) {
      ++build_failures;
      ADD_FAILURE() << "seed " << seed << " does not build (" << stage << "): " << std::string(e.what()).substr(0, 1500)
                    << "\n" << yaml;
    } catch (const std::exception& e) {
      ++crashes;
      ADD_FAILURE() << "seed " << seed << " threw at " << stage << ": " << e.what() << "\n" << yaml;
    }
  }
  std::string why;
  for (const auto& [msg, n] : refusals) why += fmt::format("\n    {} x {}", n, msg);
  std::printf("random scenes (shard %d of %d): %d accepted, %d refused, %d build failures, %d other errors, "
              "%d NaN images; widths 1 vs 16: %d of %d identical; %d built in double, at most %.1f%% of channels "
              "off by > 0.05 from float%s\n",
              GetParam(), kShards, accepted, refused, build_failures, crashes, nonfinite,
              width_checks - width_mismatches, width_checks, double_builds, 100 * worst_precision, why.c_str());
  EXPECT_EQ(build_failures, 0);
  EXPECT_EQ(crashes, 0);
  EXPECT_GT(accepted, refused) << "the generator should make valid scenes";
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomScenes, ::testing::Range(0, kShards));

TEST(RandomSceneGenerator, IsDeterministicAndVaried) {
  EXPECT_EQ(random_scene(7), random_scene(7));
  EXPECT_NE(random_scene(7), random_scene(8));
}

}  // namespace
}  // namespace sdfc::test
