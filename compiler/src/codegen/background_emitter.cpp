// What a ray that leaves the scene sees: the background gradient, or the
// analytic sky (background.sky), as one call on `rd`.
#include <fmt/format.h>

#include "entry_emitters.hpp"

namespace sdfc::codegen::detail {

std::string background_call(const ir::RenderPlan& plan, const Literals& lit, std::set<std::string>& used) {
  const ir::Sky& sky = plan.background.sky;
  if (!sky.enabled) {
    used.insert("shade_background");
    return fmt::format("shade_background(rd, {}, {}, {})", lit.vec3(plan.camera.up), lit.vec3(plan.background.top),
                       lit.vec3(plan.background.bottom));
  }
  used.insert("shade_sky");
  return fmt::format("shade_sky(rd, {}, {}, {}, {}, {}, {}, {})", lit.vec3(plan.camera.up), lit.vec3(sky.sun_direction),
                     lit.vec3(sky.zenith), lit.vec3(sky.horizon), lit.vec3(sky.ground), lit.vec3(sky.glow),
                     lit.real(sky.glow_power));
}

}  // namespace sdfc::codegen::detail
