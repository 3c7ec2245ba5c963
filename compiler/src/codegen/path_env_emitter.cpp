// background.map in the path integrator: the map's radiance where a path
// leaves the scene, and one light sample drawn from the map at each vertex,
// the two combined by multiple importance sampling (the power heuristic).
// The map reaches the kernel as the buffer argument `envmap`; only its size
// and orientation are in the source. A scene without a map holds none of it.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "entry_emitters.hpp"
#include "shading_emitter.hpp"

namespace sdfc::codegen::detail {

namespace {
using V = ir::Vec3d;
V scale(V a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
V unit(V a) { return scale(a, 1.0 / std::sqrt(dot(a, a))); }

// The map's frame: its top row towards the camera's up, its centre along -z
// (+y when up is along z), turned by `rotation` about up.
std::string frame_args(const ir::RenderPlan& plan, const Literals& lit) {
  const V up = unit(plan.camera.up);
  V e0 = sub(V{0, 0, -1}, scale(up, -up[2]));
  if (dot(e0, e0) < 1e-6) e0 = sub(V{0, 1, 0}, scale(up, up[1]));
  e0 = unit(e0);
  V e1 = cross(e0, up);  // to the right of the centre, seen from inside
  const double a = plan.background.map.rotation * std::numbers::pi / 180;
  const V r0 = sub(scale(e0, std::cos(a)), scale(e1, std::sin(a)));
  const V r1 = cross(r0, up);
  return fmt::format("{}, {}, {}", lit.vec3(r0), lit.vec3(r1), lit.vec3(up));
}

std::string env_fn(const ir::RenderPlan& plan, const Literals& lit, const char* fn, const std::string& dir) {
  const ir::EnvironmentMap& e = plan.background.map;
  return fmt::format("{}(envmap, {}, {}, {}, {})", fn, e.width, e.height, dir, frame_args(plan, lit));
}
}  // namespace

bool env_map_used(const ir::RenderPlan& plan) {
  return plan.transport.integrator == ir::Transport::Integrator::Path && plan.background.map.enabled;
}

void env_escape(CodeWriter& w, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used) {
  used.insert("env_lookup");
  used.insert("env_pdf");
  w.line(fmt::format("vec3 env = {};", env_fn(plan, lit, "env_lookup", "rd")));
  if (!plan.background.map.visible) {
    w.line("// background.visible: false: camera rays see the gradient, paths the map");
    w.line(fmt::format("if (seg == 0) env = {};", background_call(plan, lit, used)));
  }
  w.line("// multiple importance sampling: the map could have drawn this direction too (power heuristic)");
  w.line(fmt::format("real pe = {} / fmax(pdf_b, K(1e-30f));", env_fn(plan, lit, "env_pdf", "rd")));
  w.line("env = v3_scale(env, SEL(1.0f / (1.0f + pe * pe), (real)(1.0f), delta));");
}

void env_light(CodeWriter& w, const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used,
               const ir::RayBounds* bounds, bool glossy, const std::string& lanes,
               const std::function<void(const std::string&, const std::string&, const std::string&)>& add) {
  used.insert("env_sample");
  w.open("{");
  w.line("// the environment map: a direction drawn from it, weighted against the bounce's density (power heuristic)");
  w.line("const scalar edim = (scalar)(512 + seg * 2);");
  w.line("real pl; vec3 e;");
  w.line(fmt::format("vec3 l = env_sample(envmap, {}, {}, path_rand(px, py, sf, edim), path_rand(px, py, sf, edim + 1.0f), {}, &pl, &e);",
                     plan.background.map.width, plan.background.map.height, frame_args(plan, lit)));
  w.line(fmt::format("real tmax = {};", lit.typed(plan.march.max_distance)));
  w.line("(void)tmax;");
  if (glossy) {
    used.insert("path_glossy_pdf");
    w.line("real pb = path_glossy_pdf(n, v, l, alpha, ps) / fmax(pl, K(1e-30f));");
  } else {
    w.line("real pb = fmax(v3_dot(n, l), K(0.0f)) * K(0.31830988618f) / fmax(pl, K(1e-30f));");
  }
  w.line("// f cos / pdf with the MIS weight; f cos comes times pi, as for the lights");
  w.line("real wl = K(0.31830988618f) / ((1.0f + pb * pb) * fmax(pl, K(1e-30f)));");
  std::string f = glossy ? "path_glossy_eval(n, v, l, diffuse, f0, alpha)" : "v3_scale(albedo, fmax(v3_dot(n, l), K(0.0f)))";
  ir::Light sky;  // the map's visibility: a hard shadow ray towards l
  sky.shadows = ir::Light::Shadows::Hard;
  std::string term = fmt::format("v3_scale(v3_mul(thr, v3_mul({}, e)), wl)", f);
  std::string sh = shadow_call(sky, "l", "tmax", lit, bounds, used);
  add(fmt::format("v3_scale({}, {})", term, sh), lanes, "seg + 1");
  w.close("}");
}

}  // namespace sdfc::codegen::detail
