// The scene functions of the kernel: each is the one scene walker
// (scene_walker.hpp) carrying what that function returns.
#include "scene_emitter.hpp"

#include "object_set_emitter.hpp"
#include "scene_walker.hpp"

namespace sdfc::codegen::detail {

namespace {

// `signature { <the walk at p> <epilogue(value)> }`
// `live`: the mask parameter of the lanes still marching, if the function has one.
// `cone`: the camera rays' cone parameter, if the function has one.
// `above`: the parameter bounding the scene's distance from above, if any.
template <class Epilogue>
std::string function(const ir::Module& m, const Literals& lit, std::set<std::string>& used, Carry carry,
                     const std::string& signature, Epilogue epilogue, const std::string& live = "",
                     const std::string& cone = "", const std::string& above = "") {
  CodeWriter w;
  SceneWalker walker(m, lit, used, w, carry);
  if (!live.empty()) walker.live_lanes = live;
  if (!cone.empty()) walker.cone = cone;
  walker.above = above;
  w.line(signature);
  w.open("{");
  kinds::Carried v = walker.emit(m.root, "p");
  epilogue(w, v);
  w.close("}");
  return w.take();
}

}  // namespace

std::string emit_scene_material(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  used.insert("mat_record");
  std::string out = "// ---- scene material: evaluated once per hit; smooth blends mix their children's materials ----\n";
  return out + function(m, lit, used, Carry::Records,
                        m.analyses.coloring_geometry ? "real scene_material(TIME_PARAM vec3 p, vec3 n, mat_record* out)"
                                                     : "real scene_material(TIME_PARAM vec3 p, mat_record* out)",
                        [](CodeWriter& w, const kinds::Carried& v) {
                          w.line("(void)" + v.d + ";");
                          w.line("*out = " + v.rec + ";");
                          w.line("return " + v.mat + ";  // the nearest material's id (the material AOV)");
                        });
}

// scene_trap and scene_iterations return the carried value, not the distance.
namespace {
void return_carried(CodeWriter& w, const kinds::Carried& v) {
  w.line("(void)" + v.d + ";");
  w.line("return " + v.mat + ";");
}
}  // namespace

std::string emit_scene_iterations(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  return "// ---- iteration count of the nearest fractal (0 elsewhere): the iterations AOV, once per pixel ----\n" +
         function(m, lit, used, Carry::Iterations, "real scene_iterations(TIME_PARAM vec3 p)", return_carried);
}

std::string emit_scene_functions(const ir::Module& m, const Literals& lit, std::set<std::string>& used) {
  used.insert("vec3_ops");
  // The marching loops (primary, shadow, glass) take the distance inline:
  // called, every live vector of the loop is saved and restored around the
  // call (a 1280x720 Mandelbulb frame: 86 ms against 96). Normals, AO and the
  // rest call one out-of-line copy, so the kernel holds the distance twice
  // or so, not once per call site (a cold build +130 ms, not +260 ms).
  // `live` masks the lanes still marching (stopped lanes' values are not
  // used): an object set's walk opens no box for the others.
  auto ret = [](CodeWriter& w, const kinds::Carried& v) {
    w.line("(void)live;");
    w.line("return " + v.d + ";");
  };
  std::string out = "// ---- scene distance: the marching loops inline this at every step ----\n";
  if (camera_cones(m)) {  // the camera rays' march passes its packet's cone; the others none
    out += function(m, lit, used, Carry::Distance,
                    "inline __attribute__((always_inline)) real scene_dist_cone(TIME_PARAM vec3 p, mask live, const os_cone cone)",
                    ret, "live", "cone");
    out += "inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live) "
           "{ return scene_dist_cone(TIME_ARG p, live, os_cone_none()); }\n";
  } else {
    out += function(m, lit, used, Carry::Distance,
                    "inline __attribute__((always_inline)) real scene_dist_inline(TIME_PARAM vec3 p, mask live)", ret,
                    "live");
  }
  out += "\n// ---- scene distance, called: every use outside the marching loops ----\n";
  // With bounded normals the hits' shading passes the lanes it uses (`live`, the hits)
  // and the packet's cone, whose list answers for the set (os_cone_shading).
  const bool below = bounded_normals(m);
  if (below) {  // normals' taps know an upper bound: the object set's walk culls by it too
    out += function(m, lit, used, Carry::Distance,
                    "__attribute__((noinline)) real scene_dist_below(TIME_PARAM vec3 p, real above, mask live, const os_cone cone)",
                    [](CodeWriter& w, const kinds::Carried& v) {
                      w.line("(void)live; (void)cone;");
                      w.line("return " + v.d + ";");
                    },
                    "live", "cone", "above");
    out += "inline real scene_dist(TIME_PARAM vec3 p) { return scene_dist_below(TIME_ARG p, K(1e30f), M_TRUE, os_cone_none()); }\n";
  } else {
    out += "__attribute__((noinline)) real scene_dist(TIME_PARAM vec3 p) { return scene_dist_inline(TIME_ARG p, M_TRUE); }\n";
  }
  const auto& ao = m.plan.effects.ambient_occlusion;
  if (ao.enabled && ao.method == ir::AmbientOcclusion::Method::NormalSamples) {
    // an occlusion probe only needs the distance where it is below the probe's height
    out += below ? "inline real scene_dist_probe(TIME_PARAM vec3 p, real below, mask live) "
                   "{ return scene_dist_below(TIME_ARG p, below, live, os_cone_none()); }\n"
                 : "inline real scene_dist_probe(TIME_PARAM vec3 p, real below, mask live) "
                   "{ (void)below; (void)live; return scene_dist(TIME_ARG p); }\n";
  }
  out += "\n// ---- scene distance with material: evaluated once per hit ----\n";
  auto with_material = [](CodeWriter& w, const kinds::Carried& v) {
    w.line("*mat = " + v.mat + ";");
    w.line("return " + v.d + ";");
  };
  if (below) {
    out += function(m, lit, used, Carry::Material,
                    "real scene_dist_mat_hit(TIME_PARAM vec3 p, mask live, const os_cone cone, real* mat)", with_material,
                    "live", "cone");
    out += "inline real scene_dist_mat(TIME_PARAM vec3 p, real* mat) "
           "{ return scene_dist_mat_hit(TIME_ARG p, M_TRUE, os_cone_none(), mat); }\n";
  } else {
    out += function(m, lit, used, Carry::Material, "real scene_dist_mat(TIME_PARAM vec3 p, real* mat)", with_material);
  }
  if (m.analyses.orbit_traps && !m.analyses.material_blend) {  // with blends, scene_material applies the traps
    out += "\n// ---- orbit trap of the nearest fractal: evaluated once per hit, for orbit-trap materials ----\n";
    out += function(m, lit, used, Carry::Trap, "real scene_trap(TIME_PARAM vec3 p)", return_carried);
  }
  return out;
}

}  // namespace sdfc::codegen::detail
