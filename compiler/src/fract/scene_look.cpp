// Background, lights, the material and the effects of an imported scene.
// These are close translations, not Mandelbulber's shading: the shape and
// camera match, the light and colour look alike.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "import_parts.hpp"

namespace sdfc::fract {
namespace {

std::string colour_of(const Params& p, const std::string& key) { return vec(p.colour(key)); }

// The main light's direction: alpha (horizontal) and beta (vertical) angles
// in degrees, in the camera's frame when main_light_position_relative.
Vec3 main_light_towards(const Params& main) {
  double a = main.number("main_light_alpha") * M_PI / 180, b = main.number("main_light_beta") * M_PI / 180;
  Vec3 l = {std::cos(a - M_PI / 2) * std::cos(b), std::sin(a - M_PI / 2) * std::cos(b), std::sin(b)};
  if (!main.boolean("main_light_position_relative")) return l;
  CameraFrame c = camera_frame(main);  // camera space: x right, y forward, z up
  Vec3 w{};
  for (size_t k = 0; k < 3; ++k) w[k] = c.right[k] * l[0] + c.forward[k] * l[1] + c.up[k] * l[2];
  return w;
}

std::string lights(const Params& main, ImportContext& w) {
  std::string o = "lights:\n";
  bool any = false;
  if (main.boolean("main_light_enable")) {
    Vec3 t = main_light_towards(main);
    std::string shadows = "none";
    double softness = 16;
    if (main.boolean("shadows_enabled")) {
      double cone = main.number("shadows_cone_angle");
      shadows = cone > 0 ? "soft" : "hard";
      if (cone > 0) softness = std::clamp(1.0 / std::tan(std::min(cone, 60.0) * M_PI / 180), 1.0, 1e4);
    }
    o += commented("  - directional:", "the main light");
    o += commented("      direction: " + vec(w.world(Vec3{-t[0], -t[1], -t[2]})), "main_light_alpha, main_light_beta");
    o += commented("      color: " + colour_of(main, "main_light_colour"), "main_light_colour");
    o += commented("      intensity: " + num(std::max(0.0, main.number("main_light_intensity"))), "main_light_intensity");
    o += commented("      shadows: " + shadows, "shadows_enabled");
    if (shadows == "soft") o += commented("      softness: " + num(softness), "1 / tan(shadows_cone_angle)");
    any = true;
  }
  for (int n = 1; n <= 4; ++n) {
    if (!main.boolean(fmt::format("aux_light_enabled_{}", n))) continue;
    o += commented("  - point:", fmt::format("aux light {}", n));
    o += commented("      position: " + vec(w.world(main.vec3(fmt::format("aux_light_position_{}", n)))), fmt::format("aux_light_position_{}", n));
    o += commented("      color: " + colour_of(main, fmt::format("aux_light_colour_{}", n)), fmt::format("aux_light_colour_{}", n));
    o += commented("      intensity: " + num(std::max(0.0, main.number(fmt::format("aux_light_intensity_{}", n)))),
                   fmt::format("aux_light_intensity_{} (falls off with 1/distance², as Mandelbulber's)", n));
    any = true;
  }
  for (const char* group : {"aux_light_volumetric", "main_light_volumetric"})
    if (!main.given_with_prefix(group).empty()) w.add(fmt::format("volumetric light ({}_*): not imported", group));
  if (!main.given_with_prefix("random_lights").empty()) w.add("random lights (random_lights_*): not imported");
  if (main.given("fake_lights_enabled") && main.boolean("fake_lights_enabled")) w.add("fake lights (fake_lights_*): not imported");
  if (!any) o += commented("  - ambient: {intensity: 0.3}", "no light is on in the file");
  return o;
}

std::string material(const Params& main, ImportContext& w) {
  std::string o = "materials:\n  surface:\n";
  o += commented("    color: " + colour_of(main, "mat1_surface_color"), "mat1_surface_color");
  o += commented("    specular: " + num(std::clamp(main.number("mat1_specular") / 10, 0.0, 1.0)), "mat1_specular / 10");
  double refl = main.number("mat1_reflectance");
  if (refl > 0) o += commented("    reflectivity: " + num(std::min(refl, 1.0)), "mat1_reflectance");
  if (main.boolean("mat1_use_colors_from_palette")) {
    std::vector<GradientStop> g = main.gradient("mat1_surface_color_gradient");
    std::sort(g.begin(), g.end(), [](const GradientStop& a, const GradientStop& b) { return a.at < b.at; });
    if (g.size() > 16) {
      w.add(fmt::format("mat1_surface_color_gradient: {} colours, sdfc takes 16; the first 16 are used", g.size()));
      g.resize(16);
    }
    if (g.size() == 1) g.push_back({1.0, g[0].color});
    o += commented("    orbit_trap:", "mat1_use_colors_from_palette: the surface gradient along an orbit trap");
    o += commented("      gradient:", "mat1_surface_color_gradient");
    double last = -1;
    for (const GradientStop& s : g) {
      double at = std::max(s.at, last + 1e-6);  // strictly ascending
      last = at;
      o += "        - {at: " + num(std::min(at, 1.0)) + ", color: " + vec(s.color) + "}\n";
    }
    double speed = main.number("mat1_coloring_speed");
    if (speed > 0) o += commented("      cycles: " + num(std::min(speed, 1000.0)), "mat1_coloring_speed");
    double offset = main.number("mat1_coloring_palette_offset");
    offset -= std::floor(offset);  // the gradient repeats: only the fraction moves it
    o += commented("      offset: " + num(offset), "mat1_coloring_palette_offset (its fraction)");
    o += "      repeat: repeat\n      mix: 1\n";
  }
  for (const char* group : {"mat1_use_color_texture", "mat1_use_diffusion_texture", "mat1_use_displacement_texture",
                            "mat1_use_normal_map_texture", "mat1_luminosity", "mat1_transparency_of_surface",
                            "mat1_iridescence_enabled"})
    if (main.given(group) && main.section().entries.at(group).value != "false" &&
        main.section().entries.at(group).value != "0")
      w.add(fmt::format("material: {} not imported", group));
  for (int m = 2; m <= 9; ++m)
    if (!main.given_with_prefix(fmt::format("mat{}_", m)).empty()) {
      w.add("materials 2 and later (matN_*): not imported; every formula takes material 1");
      break;
    }
  return o;
}

std::string effects(const Params& main, ImportContext& w) {
  std::string o;
  if (main.boolean("ambient_occlusion_enabled")) {
    int quality = std::clamp(main.integer("ambient_occlusion_quality"), 1, 64);
    double strength = std::clamp(main.number("ambient_occlusion"), 0.0, 100.0);
    double distance = camera_frame(main).distance * 0.05;
    o += commented("  ambient_occlusion:", "ambient_occlusion_enabled");
    o += commented("    samples: " + std::to_string(quality), "ambient_occlusion_quality");
    o += commented("    strength: " + num(strength), "ambient_occlusion");
    o += commented("    distance: " + num(distance), "5 % of the camera's distance to its target");
  }
  if (main.boolean("glow_enabled") && main.number("glow_intensity") > 0) {
    o += commented("  glow:", "glow_enabled: Mandelbulber's glow counts the march's steps");
    o += commented("    color: " + colour_of(main, "glow_color_1"), "glow_color_1");
    o += commented("    strength: 0", "");
    o += commented("    step_strength: " + num(std::min(main.number("glow_intensity"), 1e4)), "glow_intensity");
  }
  if (main.boolean("basic_fog_enabled")) {
    double vis = main.number("basic_fog_visibility");
    if (vis > 0) {
      o += commented("  fog:", "basic_fog_enabled");
      o += commented("    color: " + colour_of(main, "basic_fog_color"), "basic_fog_color");
      // sdfc's density stops at 1000 (a fog that hides everything 1/1000 away).
      o += commented("    density: " + num(std::min(1.0 / vis, 1000.0)), vis < 1e-3 ? "1 / basic_fog_visibility, at sdfc's cap 1000"
                                                                              : "1 / basic_fog_visibility");
    }
  }
  if (main.boolean("raytraced_reflections") && main.number("mat1_reflectance") > 0)
    o += commented("  reflections: {depth: " + std::to_string(std::clamp(main.integer("reflections_max"), 0, 8)) + "}",
                   "raytraced_reflections, reflections_max");
  if (main.given("volumetric_fog_enabled") && main.boolean("volumetric_fog_enabled")) w.add("volumetric fog: not imported");
  if (main.given("iteration_fog_enable") && main.boolean("iteration_fog_enable")) w.add("iteration fog: not imported");
  if (main.given("hdr_blur_enabled") && main.boolean("hdr_blur_enabled")) w.add("HDR blur (hdr_blur_*): not imported");
  return o.empty() ? "" : "effects:\n" + o;
}

}  // namespace

std::string import_look(const File&, const Params& main, ImportContext& w) {
  std::string o = "background:\n";
  o += commented("  top: " + colour_of(main, "background_color_1"), "background_color_1");
  o += commented("  bottom: " + colour_of(main, "background_color_3"), "background_color_3");
  if (main.given("background_color_2")) w.add("background: the middle colour background_color_2 is not imported");
  if ((main.given("textured_background") && main.boolean("textured_background")) ||
      (main.given("env_mapping_enable") && main.boolean("env_mapping_enable")))
    w.add("background and environment textures: not imported");
  return o + lights(main, w) + material(main, w) + effects(main, w);
}

}  // namespace sdfc::fract
