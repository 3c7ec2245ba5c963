#include "render_helpers.hpp"

#include <cmath>
#include <numbers>

#include "scene_text.hpp"
#include "sdfc/codegen/emit_opencl.hpp"
#include "sdfc/passes/passes.hpp"

namespace sdfc::test {

sdfrt::Device& device() {
  static sdfrt::Device d = sdfrt::open_device(std::nullopt);
  return d;
}

ir::Module compile_text(const std::string& scene) { return passes::run_pipeline(lower_text(scene)); }

Rendered render_text(const std::string& scene, int simd_width, int tile, int packet_rows) {
  return render_module(compile_text(scene), simd_width, tile, packet_rows);
}

Rendered render_module(ir::Module module, int simd_width, int tile, int packet_rows) {
  Rendered r{std::move(module), {}};
  codegen::EmitOptions opt;
  opt.simd_width = simd_width;
  opt.packet_rows = packet_rows;
  opt.aovs = true;
  codegen::EmittedKernel k = codegen::emit_opencl(r.module, opt);
  sdfrt::Renderer renderer(device(), {k.source, k.entry, k.simd_width, k.packet_rows, k.planes, "", k.scene_data, k.environment});
  const int w = r.module.plan.march.width, h = r.module.plan.march.height;
  sdfrt::RenderOptions ro;
  ro.tile_width = ro.tile_height = tile;
  r.image = renderer.render(codegen::frame_params(r.module.plan, w, h), w, h, ro);
  return r;
}

Pixel project(const ir::RenderPlan& plan, ir::Vec3d p) {
  const ir::Camera& c = plan.camera;
  auto sub = [](ir::Vec3d a, ir::Vec3d b) { return ir::Vec3d{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto dot = [](ir::Vec3d a, ir::Vec3d b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross = [](ir::Vec3d a, ir::Vec3d b) {
    return ir::Vec3d{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto norm = [&](ir::Vec3d a) {
    double l = std::sqrt(dot(a, a));
    return ir::Vec3d{a[0] / l, a[1] / l, a[2] / l};
  };
  ir::Vec3d fw = norm(sub(c.target, c.position)), rt = norm(cross(fw, c.up)), up = cross(rt, fw);
  double th = std::tan(c.fov_degrees * std::numbers::pi / 360.0);
  double aspect = double(plan.march.width) / plan.march.height;
  ir::Vec3d d = sub(p, c.position);
  double z = dot(d, fw);
  double u = dot(d, rt) / (z * th * aspect), v = dot(d, up) / (z * th);
  return {int(std::floor((u + 1) * 0.5 * plan.march.width)), int(std::floor((1 - v) * 0.5 * plan.march.height))};
}

std::optional<ir::Vec3d> world_point(const Rendered& r, int x, int y) {
  float depth = r.image.at(3, x, y);
  if (depth < 0) return std::nullopt;
  const int w = r.image.width, h = r.image.height;
  std::vector<float> f = codegen::frame_params(r.module.plan, w, h);
  auto f3 = [&](int i) { return ir::Vec3d{double(f[i]) + f[i + 3], double(f[i + 1]) + f[i + 4], double(f[i + 2]) + f[i + 5]}; };
  ir::Vec3d ro = f3(0), fw = f3(6), rt = f3(12), up = f3(18);
  double u = 2.0 * (x + 0.5) / w - 1, v = 1 - 2.0 * (y + 0.5) / h;
  ir::Vec3d d{fw[0] + rt[0] * u + up[0] * v, fw[1] + rt[1] * u + up[1] * v, fw[2] + rt[2] * u + up[2] * v};
  double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return ir::Vec3d{ro[0] + d[0] / len * depth, ro[1] + d[1] / len * depth, ro[2] + d[2] / len * depth};
}

float brightness(const sdfrt::FloatImage& img, Pixel px) {
  return (img.at(0, px.x, px.y) + img.at(1, px.x, px.y) + img.at(2, px.x, px.y)) / 3.0f;
}

}  // namespace sdfc::test
