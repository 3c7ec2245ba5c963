#include "conformance.hpp"

#include "sdfc/reference/at_time.hpp"

#include <fmt/format.h>

#include <cstring>

namespace sdfc::conformance {

const std::vector<EvalConfig>& eval_configs() {
  static const std::vector<EvalConfig> c = {{1, false}, {8, false},  {16, false}, {64, false},
                                            {1, true},  {8, true},   {16, true},  {64, true}};
  return c;
}

namespace {
std::string pt(const V3& p) { return fmt::format("({:.9g}, {:.9g}, {:.9g})", p[0], p[1], p[2]); }
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

ProbeCheck probe_and_compare(const ir::Module& m, const EvalConfig& cfg, std::vector<V3> points,
                             const Tolerance& tol, const std::vector<char>& check_material, double time) {
  ProbeCheck pc;
  for (auto& p : points) p = test::to_float_point(p);
  pc.points = std::move(points);
  ir::Module then = reference::at_time(m, time);
  for (const auto& p : pc.points) {
    reference::Sample s = reference::evaluate(*then.graph, then.root, p);
    pc.ref_d.push_back(s.distance);
    pc.ref_mat.push_back(s.material);
  }
  test::Probe probe(m, cfg.simd_width);
  pc.got = probe.run(pc.points, time);

  int bad_d = 0, bad_dm = 0, bad_mat = 0, checked_mat = 0;
  double worst = 0;  // largest |error| / allowed
  std::string msgs;
  auto note = [&](int& count, const std::string& what) {
    if (count++ < 5) msgs += what + "\n";
  };
  for (size_t i = 0; i < pc.points.size(); ++i) {
    double ref = pc.ref_d[i];
    double got = pc.got.d[i];
    double err = std::fabs(got - ref);
    double allowed = tol.allowed(ref);
    if (tol.sign_only(ref) ? !(got < 0) : !(err <= allowed))  // also catches NaN
      note(bad_d, fmt::format("  distance at {}: reference {:.10g}, kernel {:.10g} (|diff| {:.3g} > {:.3g})",
                              pt(pc.points[i]), ref, got, err, allowed));
    else if (!tol.sign_only(ref))
      worst = std::max(worst, err / allowed);
    if (!same_bits(pc.got.d[i], pc.got.d_mat[i]))
      note(bad_dm, fmt::format("  scene_dist {:.10g} != scene_dist_mat {:.10g} at {}", pc.got.d[i],
                               pc.got.d_mat[i], pt(pc.points[i])));
    if (check_material.empty() || check_material[i]) {
      ++checked_mat;
      if (pc.got.mat[i] != float(pc.ref_mat[i]))
        note(bad_mat, fmt::format("  material at {}: reference {}, kernel {}", pt(pc.points[i]), pc.ref_mat[i],
                                  pc.got.mat[i]));
    }
  }
  EXPECT_EQ(bad_d, 0) << bad_d << " of " << pc.points.size() << " distances out of tolerance (" << cfg.name()
                      << "):\n" << msgs;
  EXPECT_EQ(bad_dm, 0) << "scene_dist and scene_dist_mat disagree:\n" << msgs;
  EXPECT_EQ(bad_mat, 0) << bad_mat << " of " << checked_mat << " material ids differ:\n" << msgs;
  ::testing::Test::RecordProperty("points", int(pc.points.size()));
  ::testing::Test::RecordProperty("worst_error_over_tolerance", fmt::format("{:.3g}", worst));
  return pc;
}

void expect_inside_bounds(const ir::Module& m, const std::vector<V3>& points) {
  const ir::Box3& b = m.graph->node(m.root).props.bounds;
  int bad = 0;
  std::string msgs;
  for (const auto& p : points) {
    if (reference::evaluate(*m.graph, m.root, p).distance > 0) continue;
    // A hair of slack: surface points come from float rounding or bisection.
    bool in = true;
    for (int i = 0; i < 3; ++i) in = in && p[i] >= b.lo[i] - 1e-6 && p[i] <= b.hi[i] + 1e-6;
    if (!in && bad++ < 5)
      msgs += fmt::format("  {} is inside the shape but outside bounds [{}, {}, {}]..[{}, {}, {}]\n", pt(p), b.lo[0],
                          b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]);
  }
  EXPECT_EQ(bad, 0) << msgs;
}

}  // namespace sdfc::conformance
