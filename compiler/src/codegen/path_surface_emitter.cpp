// The path integrator's per-material values: which parts the
// scene's materials need, and path_surface(), their select chain.
#include <fmt/format.h>

#include <algorithm>

#include "entry_emitters.hpp"
#include "kernel_text.hpp"

namespace sdfc::codegen::detail {

bool any_glossy(const ir::RenderPlan& p) {
  for (const auto& md : p.materials) if (md.glossy) return true;
  return false;
}

bool any_emission(const ir::RenderPlan& p) {
  for (const auto& md : p.materials) if (md.emission[0] > 0 || md.emission[1] > 0 || md.emission[2] > 0) return true;
  return false;
}

bool any_glass(const ir::RenderPlan& p) {
  for (const auto& md : p.materials) if (md.glass) return true;
  return false;
}

// path_surface(id, ...): the path integrator's per-material values beside
// material_of's albedo: emission, roughness as GGX alpha, metalness, glass.
std::string surface_table(const ir::RenderPlan& plan, bool glossy, bool emission, bool glass, const Literals& lit) {
  CodeWriter w;
  std::string params = std::string(emission ? ", vec3* emission" : "") + (glossy ? ", real* alpha, real* metal, mask* lobe" : "") +
                       (glass ? ", mask* glass, real* ior, vec3* sigma" : "");
  std::string parts;
  for (auto [on, name] : {std::pair{emission, "emission"}, {glossy, "GGX alpha, metalness"}, {glass, "glass, index, absorption"}})
    if (on) parts += (parts.empty() ? "" : ", ") + std::string(name);
  w.line(fmt::format("// ---- the path integrator's materials: id -> {} ----", parts));
  w.line("void path_surface(real id" + params + ")");
  w.open("{");
  const auto& mats = plan.materials;
  auto values = [&](const ir::MaterialDef& md, const std::string& cond) {
    double alpha = std::max(md.roughness * md.roughness, 2e-3);  // roughness 0 stays a (very) sharp lobe
    if (cond.empty()) {
      if (emission) w.line(fmt::format("*emission = {};", lit.vec3(md.emission)));
      if (glossy) w.line(fmt::format("*alpha = {}; *metal = {}; *lobe = {};", lit.typed(alpha), lit.typed(md.metalness),
                                     md.glossy ? "M_TRUE" : "!M_TRUE"));
      if (glass) w.line(fmt::format("*glass = {}; *ior = {}; *sigma = {};", md.glass ? "M_TRUE" : "!M_TRUE", lit.typed(md.ior),
                                    lit.vec3(md.absorption)));
      return;
    }
    if (emission) w.line(fmt::format("*emission = v3_select(*emission, {}, {});", lit.vec3(md.emission), cond));
    if (glossy) {
      w.line(fmt::format("*alpha = SEL(*alpha, {}, {});", lit.typed(alpha), cond));
      w.line(fmt::format("*metal = SEL(*metal, {}, {});", lit.typed(md.metalness), cond));
      w.line(fmt::format("*lobe = *lobe {} {};", md.glossy ? "|" : "& !", cond));
    }
    if (glass) {
      w.line(fmt::format("*glass = *glass {} {};", md.glass ? "|" : "& !", cond));
      w.line(fmt::format("*ior = SEL(*ior, {}, {});", lit.typed(md.ior), cond));
      w.line(fmt::format("*sigma = v3_select(*sigma, {}, {});", lit.vec3(md.absorption), cond));
    }
  };
  w.line(fmt::format("// material 0 '{}'", kernel_text(mats[0].name)));
  values(mats[0], "");
  if (mats.size() == 1) w.line("(void)id;");
  for (size_t i = 1; i < mats.size(); ++i) {
    w.line(fmt::format("// material {} '{}'", i, kernel_text(mats[i].name)));
    values(mats[i], fmt::format("(id == {})", lit.real(double(i))));
  }
  w.close("}");
  return w.take();
}

}  // namespace sdfc::codegen::detail
