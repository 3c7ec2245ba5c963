// Smooth glass in the path integrator: at a vertex on a glass
// material, Fresnel's exact reflectance chooses between the mirrored and
// the refracted direction (both delta lobes, so the throughput is kept as
// it is); a refracted path changes side, and the segment it then marches
// inside the solid runs on the negated distance (march_signed) and is
// dimmed by Beer-Lambert absorption when it ends.
#include "entry_emitters.hpp"

namespace sdfc::codegen::detail {

void glass_scatter(CodeWriter& w) {
  w.line("// glass: reflect with the exact Fresnel reflectance, else refract (Snell); total internal reflection reflects");
  w.line("real ci = clamp(v3_dot(n, v), K(0.0f), K(1.0f));  // n faces the incoming ray");
  w.line("real eta = SEL(1.0f / ior, ior, inside);  // index of the side the ray comes from over the other's");
  w.line("real s2 = eta * eta * fmax(1.0f - ci * ci, K(0.0f));");
  w.line("real ct = sqrt(fmax(1.0f - s2, K(0.0f)));");
  w.line("real fr = SEL(glass_fresnel(ci, ct, eta), (real)(1.0f), s2 >= 1.0f);");
  w.line("mask refract = on_glass & (u0 >= fr);");
  w.line("vec3 mirrored = v3_mad(rd, n, 2.0f * ci);");
  w.line("vec3 refracted = v3_normalize(v3_add(v3_scale(rd, eta), v3_scale(n, eta * ci - ct)));");
  w.line("nd = v3_select(nd, v3_select(mirrored, refracted, refract), on_glass);");
  w.line("thr = v3_select(thr, thr_in, on_glass);  // F / F and (1 - F) / (1 - F): the throughput stays");
  w.line("// a refracted path starts on the other side of the surface, inside the solid or back outside it");
  w.line("start = v3_select(start, v3_mad(p, n, -2.0f * footprint), refract);");
  w.line("sigma_in = v3_select(sigma_in, sigma, refract & !inside);");
  w.line("inside = (inside & !refract) | (refract & !inside);");
}

}  // namespace sdfc::codegen::detail
