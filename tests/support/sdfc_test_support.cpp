#include "sdfc_test_support.hpp"

#include <CL/cl.h>
#include <fmt/format.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sdfc/compile.hpp"
#include "sdfc/source/overrides.hpp"
#include "sdfc/source/yaml_loader.hpp"

namespace sdfc::test {

sdfrt::Device& device() {
  static sdfrt::Device dev = [] {
    // Build every kernel from source unless the caller chose otherwise: the
    // suites then test this build's compiler output, never a binary cached
    // by an earlier run, and a cold run stays fast (writing cache entries
    // makes PoCL generate binaries, which doubles the build time: ~75 s
    // instead of ~30 s for conformance_tests with empty caches). PoCL's own
    // kernel cache still makes warm runs quick. Child processes (the CLI
    // test) inherit the setting.
    ::setenv("SDFC_KERNEL_CACHE", "0", /*overwrite=*/0);
    return sdfrt::open_device();
  }();
  return dev;
}

ir::Module compile_text(const std::string& yaml, const std::string& name, const std::vector<std::string>& overrides) {
  SourceValue doc = load_yaml_text(yaml, name);
  apply_overrides(doc, overrides);
  return build_module(doc, name);
}

// ---- probe ----------------------------------------------------------------

namespace {

void check(cl_int err, const char* what) {
  if (err != CL_SUCCESS) throw std::runtime_error(fmt::format("{} failed with OpenCL error {}", what, err));
}

sdfrt::BufferHandle make_buffer(cl_context ctx, cl_mem_flags flags, size_t floats, const float* init) {
  cl_int err = CL_SUCCESS;
  cl_mem m = clCreateBuffer(ctx, flags | (init ? CL_MEM_COPY_HOST_PTR : 0), floats * sizeof(float),
                            const_cast<float*>(init), &err);
  check(err, "clCreateBuffer");
  return sdfrt::BufferHandle(m);
}

// The points' coordinates as three float buffers, padded with zeros to a
// whole number of `simd_width`-point packets (at least one).
struct PointBuffers {
  size_t padded;
  sdfrt::BufferHandle x, y, z;
};

PointBuffers upload_points(const std::vector<V3>& points, size_t simd_width) {
  const size_t n = points.size();
  const size_t padded = std::max<size_t>(simd_width, (n + simd_width - 1) / simd_width * simd_width);
  std::vector<float> x(padded, 0.0f), y(padded, 0.0f), z(padded, 0.0f);
  for (size_t i = 0; i < n; ++i) {
    x[i] = static_cast<float>(points[i][0]);
    y[i] = static_cast<float>(points[i][1]);
    z[i] = static_cast<float>(points[i][2]);
  }
  cl_context ctx = device().context();
  return {padded, make_buffer(ctx, CL_MEM_READ_ONLY, padded, x.data()), make_buffer(ctx, CL_MEM_READ_ONLY, padded, y.data()),
          make_buffer(ctx, CL_MEM_READ_ONLY, padded, z.data())};
}

}  // namespace

Probe::Probe(const ir::Module& m, int simd_width) {
  emitted_ = codegen::emit_opencl(m, {simd_width, true});
  program_.emplace(sdfrt::build_program(device(), emitted_.source, ""));
  kernel_.emplace(program_->kernel("sdfc_probe"));
}

ProbeResult Probe::run(const std::vector<V3>& points, double time) {
  const size_t n = points.size();
  PointBuffers in = upload_points(points, static_cast<size_t>(emitted_.simd_width));
  const size_t w = static_cast<size_t>(emitted_.simd_width), padded = in.padded;
  cl_context ctx = device().context();
  cl_command_queue q = device().queue();
  auto bd = make_buffer(ctx, CL_MEM_WRITE_ONLY, padded, nullptr);
  auto bdm = make_buffer(ctx, CL_MEM_WRITE_ONLY, padded, nullptr);
  auto bm = make_buffer(ctx, CL_MEM_WRITE_ONLY, padded, nullptr);
  cl_mem args[6] = {in.x.get(), in.y.get(), in.z.get(), bd.get(), bdm.get(), bm.get()};
  for (unsigned i = 0; i < 6; ++i) kernel_->set_arg(i, args[i]);
  kernel_->set_arg(6, static_cast<float>(time));
  sdfrt::BufferHandle data;  // object sets: their numbers are the probe's last argument
  if (!emitted_.scene_data.empty()) {
    data = make_buffer(ctx, CL_MEM_READ_ONLY, emitted_.scene_data.size(), emitted_.scene_data.data());
    kernel_->set_arg(7, data.get());
  }
  size_t global = padded / w;
  check(clEnqueueNDRangeKernel(q, kernel_->get(), 1, nullptr, &global, nullptr, 0, nullptr, nullptr),
        "clEnqueueNDRangeKernel(sdfc_probe)");
  ProbeResult r;
  r.d.resize(padded);
  r.d_mat.resize(padded);
  r.mat.resize(padded);
  check(clEnqueueReadBuffer(q, bd.get(), CL_FALSE, 0, padded * sizeof(float), r.d.data(), 0, nullptr, nullptr),
        "clEnqueueReadBuffer");
  check(clEnqueueReadBuffer(q, bdm.get(), CL_FALSE, 0, padded * sizeof(float), r.d_mat.data(), 0, nullptr, nullptr),
        "clEnqueueReadBuffer");
  check(clEnqueueReadBuffer(q, bm.get(), CL_TRUE, 0, padded * sizeof(float), r.mat.data(), 0, nullptr, nullptr),
        "clEnqueueReadBuffer");
  r.d.resize(n);
  r.d_mat.resize(n);
  r.mat.resize(n);
  return r;
}

std::vector<std::array<float, 6>> Probe::run_material(const std::vector<V3>& points) {
  sdfrt::Kernel kernel = program_->kernel("sdfc_probe_material");
  const size_t n = points.size();
  PointBuffers in = upload_points(points, static_cast<size_t>(emitted_.simd_width));
  const size_t w = static_cast<size_t>(emitted_.simd_width), padded = in.padded;
  cl_context ctx = device().context();
  cl_command_queue q = device().queue();
  auto bo = make_buffer(ctx, CL_MEM_WRITE_ONLY, 6 * padded, nullptr);
  cl_mem args[4] = {in.x.get(), in.y.get(), in.z.get(), bo.get()};
  for (unsigned i = 0; i < 4; ++i) kernel.set_arg(i, args[i]);
  cl_int planes = static_cast<cl_int>(padded);
  kernel.set_arg(4, planes);
  kernel.set_arg(5, 0.0f);  // probe_time: the material probes run static scenes
  sdfrt::BufferHandle data;
  if (!emitted_.scene_data.empty()) {
    data = make_buffer(ctx, CL_MEM_READ_ONLY, emitted_.scene_data.size(), emitted_.scene_data.data());
    kernel.set_arg(6, data.get());
  }
  size_t global = padded / w;
  check(clEnqueueNDRangeKernel(q, kernel.get(), 1, nullptr, &global, nullptr, 0, nullptr, nullptr),
        "clEnqueueNDRangeKernel(sdfc_probe_material)");
  std::vector<float> out(6 * padded);
  check(clEnqueueReadBuffer(q, bo.get(), CL_TRUE, 0, out.size() * sizeof(float), out.data(), 0, nullptr, nullptr),
        "clEnqueueReadBuffer");
  std::vector<std::array<float, 6>> r(n);
  for (size_t i = 0; i < n; ++i)
    for (size_t c = 0; c < 6; ++c) r[i][c] = out[c * padded + i];
  return r;
}

std::vector<float> run_point_kernel(const std::string& source, const std::string& name, const std::vector<V3>& points,
                                    int simd_width) {
  sdfrt::Program program = sdfrt::build_program(device(), source, "");
  sdfrt::Kernel kernel = program.kernel(name);
  const size_t w = static_cast<size_t>(simd_width), n = points.size();
  PointBuffers in = upload_points(points, w);
  const size_t padded = in.padded;
  cl_command_queue q = device().queue();
  auto bo = make_buffer(device().context(), CL_MEM_WRITE_ONLY, padded, nullptr);
  cl_mem args[4] = {in.x.get(), in.y.get(), in.z.get(), bo.get()};
  for (unsigned i = 0; i < 4; ++i) kernel.set_arg(i, args[i]);
  size_t global = padded / w;
  check(clEnqueueNDRangeKernel(q, kernel.get(), 1, nullptr, &global, nullptr, 0, nullptr, nullptr),
        "clEnqueueNDRangeKernel");
  std::vector<float> out(padded);
  check(clEnqueueReadBuffer(q, bo.get(), CL_TRUE, 0, padded * sizeof(float), out.data(), 0, nullptr, nullptr),
        "clEnqueueReadBuffer");
  out.resize(n);
  return out;
}

double round_to_float(double x) {
  // volatile: GCC 12.2 at -O2 (SLP vectorizer) drops the double->float->double
  // round trip when it is written as plain casts over an array, which gave
  // back the unrounded coordinates.
  volatile float f = static_cast<float>(x);
  return f;
}

V3 to_float_point(const V3& p) { return {round_to_float(p[0]), round_to_float(p[1]), round_to_float(p[2])}; }

// ---- vectors --------------------------------------------------------------

double norm(const V3& a) { return std::sqrt(dot(a, a)); }
V3 normalize(const V3& a) { return mul(a, 1.0 / norm(a)); }

Quat Quat::axis_angle(const V3& axis, double degrees) {
  V3 u = normalize(axis);
  double h = degrees * std::numbers::pi / 360.0;  // half angle
  double s = std::sin(h);
  return {std::cos(h), u[0] * s, u[1] * s, u[2] * s};
}

Quat Quat::operator*(const Quat& o) const {
  return {w * o.w - x * o.x - y * o.y - z * o.z, w * o.x + x * o.w + y * o.z - z * o.y,
          w * o.y - x * o.z + y * o.w + z * o.x, w * o.z + x * o.y - y * o.x + z * o.w};
}

V3 Quat::rotate(const V3& v) const {
  Quat r = (*this) * Quat{0, v[0], v[1], v[2]} * conj();
  return {r.x, r.y, r.z};
}

// ---- points ---------------------------------------------------------------

V3 uniform_in(std::mt19937_64& rng, const V3& lo, const V3& hi) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  V3 p;
  for (int i = 0; i < 3; ++i) p[i] = lo[i] + (hi[i] - lo[i]) * u(rng);
  return p;
}

V3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  V3 v{g(rng), g(rng), g(rng)};
  return normalize(v);
}

Ray random_ray(std::mt19937_64& rng, const V3& centre, double from, double to) {
  V3 o = add(centre, mul(random_unit(rng), from));
  V3 aim = add(centre, mul(random_unit(rng), to));
  return {o, normalize(sub(aim, o))};
}

}  // namespace sdfc::test
