#pragma once
// Helpers shared by the conformance and end-to-end suites: one OpenCL device
// per test process, scenes compiled from YAML text, the generated
// `sdfc_probe` kernel run on real points, small vector maths (and, from
// test_files.hpp, temp dirs and file reads).
#include <sdfrt/device.hpp>
#include <sdfrt/program.hpp>

#include <array>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/ir/module.hpp"
#include "sdfc/reference/evaluator.hpp"
#include "test_files.hpp"

namespace sdfc::test {

using V3 = std::array<double, 3>;

// ---- device and scenes ----------------------------------------------------

// The default device (open_device()), opened once per test process. The
// first call also sets SDFC_KERNEL_CACHE=0 unless it is already set, so
// kernels are built from source (see the .cpp for why).
sdfrt::Device& device();

// YAML text -> optimised module (load_yaml_text + overrides + build_module).
ir::Module compile_text(const std::string& yaml, const std::string& name = "test.yaml",
                        const std::vector<std::string>& overrides = {});

// ---- the probe kernel -----------------------------------------------------

struct ProbeResult {
  std::vector<float> d;      // scene_dist
  std::vector<float> d_mat;  // scene_dist_mat's distance
  std::vector<float> mat;    // scene_dist_mat's material id
};

// A module compiled with emit_opencl(..., probe_kernel = true) and built once;
// run() evaluates any number of points in one launch.
class Probe {
 public:
  Probe(const ir::Module& m, int simd_width);
  // The points are passed as floats (the probe's ABI); callers should
  // evaluate the reference at the same float-rounded coordinates
  // (see to_float_point).
  // `time`: the frame time of an animated scene (ignored by a static one).
  ProbeResult run(const std::vector<V3>& points, double time = 0);
  // The blended material (sdfc_probe_material, emitted only for scenes with
  // a smooth blend of differing materials): per point albedo r, g, b,
  // specular, shininess, reflectivity.
  std::vector<std::array<float, 6>> run_material(const std::vector<V3>& points);
  const codegen::EmittedKernel& emitted() const { return emitted_; }

 private:
  codegen::EmittedKernel emitted_;
  std::optional<sdfrt::Program> program_;
  std::optional<sdfrt::Kernel> kernel_;
};

// Builds `source` and runs its kernel `name(px, py, pz, out)` (three float
// coordinate arrays in, one float per point out, one work-item per
// `simd_width` points) once over all the points; returns out per point.
// For a test's own probe kernel appended to an emitted scene kernel.
std::vector<float> run_point_kernel(const std::string& source, const std::string& name, const std::vector<V3>& points,
                                    int simd_width);

// The point as the probe sees it: each coordinate rounded to float.
V3 to_float_point(const V3& p);
double round_to_float(double x);

// ---- vectors --------------------------------------------------------------

inline V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 mul(const V3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const V3& a);
V3 normalize(const V3& a);

// Rotation by a unit quaternion built from axis/angle (degrees). Written with
// quaternions on purpose: the frontend uses Rodrigues' matrix, so the tests
// check it with an independent construction.
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
  static Quat axis_angle(const V3& axis, double degrees);
  Quat operator*(const Quat& o) const;
  Quat conj() const { return {w, -x, -y, -z}; }
  V3 rotate(const V3& v) const;
};

// A similarity transform p_world = translate + R (scale * p_local), the
// order sdfc applies a node's modifiers in (scale, then rotate, then translate).
struct Similarity {
  double scale = 1;
  Quat rot;
  V3 translate{0, 0, 0};
  V3 to_world(const V3& local) const { return add(translate, rot.rotate(mul(local, scale))); }
  V3 to_local(const V3& world) const { return mul(rot.conj().rotate(sub(world, translate)), 1.0 / scale); }
};

// ---- points ---------------------------------------------------------------

V3 uniform_in(std::mt19937_64& rng, const V3& lo, const V3& hi);
V3 random_unit(std::mt19937_64& rng);

// Points on the zero set of `f` (bisection to 1e-9 along random segments in
// the box whose ends have opposite signs). Returns fewer than `n` only if the
// surface is hard to find in the box.
template <typename F>
std::vector<V3> surface_points(F&& f, const V3& lo, const V3& hi, size_t n, std::mt19937_64& rng) {
  std::vector<V3> out;
  for (size_t attempt = 0; attempt < 200 * n && out.size() < n; ++attempt) {
    V3 a = uniform_in(rng, lo, hi), b = uniform_in(rng, lo, hi);
    double fa = f(a), fb = f(b);
    if ((fa < 0) == (fb < 0)) continue;
    for (int i = 0; i < 60; ++i) {
      V3 m = mul(add(a, b), 0.5);
      double fm = f(m);
      if ((fm < 0) == (fa < 0)) a = m, fa = fm; else b = m, fb = fm;
      if (norm(sub(a, b)) < 1e-9) break;
    }
    out.push_back(mul(add(a, b), 0.5));
  }
  return out;
}

// A ray from a random point at distance `from` of `centre` towards a random
// point at distance `to` of it (|rd| = 1).
struct Ray {
  V3 o, rd;
};
Ray random_ray(std::mt19937_64& rng, const V3& centre, double from, double to);

// Sphere tracing of the ray o + t rd against the distance bound `f` from
// t = 0: the first t where f < eps, or nullopt once t reaches t_max or after
// max_steps steps.
template <typename F>
std::optional<double> trace_to_surface(F&& f, const V3& o, const V3& rd, double eps, double t_max, int max_steps = 3000) {
  double t = 0;
  for (int i = 0; i < max_steps && t < t_max; ++i) {
    double d = f(add(o, mul(rd, t)));
    if (d < eps) return t;
    t += d;
  }
  return std::nullopt;
}

}  // namespace sdfc::test
