// Keys Mandelbulber renamed between versions. A file is read under the names
// of 2.20 (whose defaults the importer carries): older files' keys are moved
// forward, as Mandelbulber's own loader does, and the light keys of 2.25 and
// later (`light1_*`, `lightN_*`) are moved back to 2.20's `main_light_*`,
// `aux_light_*_N`.
#include <string>
#include <string_view>

#include "fract_internal.hpp"
#include "sdfc/fract/fract_file.hpp"

namespace sdfc::fract {
namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

void replace_all(std::string& s, std::string_view from, std::string_view to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
}

// 2.071 moved the surface settings into the first material.
constexpr std::string_view kMaterialKeys[] = {
    "shading", "specular", "fresnel_reflectance", "coloring_random_seed", "coloring_saturation", "coloring_speed",
    "coloring_palette_size", "coloring_palette_offset", "surface_color_palette", "fractal_coloring_algorithm",
    "fractal_coloring_sphere_radius", "fractal_coloring_line_direction"};

// 2.25's names of the main light, back to 2.20's.
struct Pair {
  std::string_view newer, older;
};
constexpr Pair kMainLight[] = {
    {"light1_intensity", "main_light_intensity"},       {"light1_visibility", "main_light_visibility"},
    {"light1_size", "main_light_visibility_size"},      {"light1_alpha", "main_light_alpha"},
    {"light1_beta", "main_light_beta"},                 {"light1_color", "main_light_colour"},
    {"light1_penetrating", "penetrating_lights"},       {"light1_cast_shadows", "shadows_enabled"},
    {"light1_soft_shadow_cone", "shadows_cone_angle"},  {"light1_enabled", "main_light_enable"},
    {"light1_relative_position", "main_light_position_relative"}};
constexpr Pair kAuxLight[] = {{"intensity", "aux_light_intensity_"},
                              {"position", "aux_light_position_"},
                              {"enabled", "aux_light_enabled_"},
                              {"color", "aux_light_colour_"}};

// surface_color_palette "c1 c2 c3 " -> surface_color_gradient "0 c1 3333 c2 6666 c3".
std::string palette_to_gradient(const std::string& value) {
  std::vector<std::string> colours;
  size_t i = 0;
  while (i < value.size()) {
    size_t j = value.find(' ', i);
    if (j == std::string::npos) j = value.size();
    if (j - i >= 6) colours.push_back(value.substr(i, j - i));
    i = j + 1;
  }
  std::string out;
  for (size_t k = 0; k < colours.size(); ++k) {
    if (k) out += ' ';
    out += std::to_string(int(double(k) / double(colours.size()) * 10000.0)) + " " + colours[k];
  }
  return out;
}

}  // namespace

void apply_renames(std::string& key, std::string& value, double version) {
  if (version <= 2.01) {
    replace_all(key, "aux_light_predefined", "aux_light");
    if (key == "volumetric_light_intensity_0") key = "main_light_volumetric_intensity";
    else if (key == "volumetric_light_enabled_0") key = "main_light_volumetric_enabled";
    else replace_all(key, "volumetric_light", "aux_light_volumetric");
  }
  if (version <= 2.04 && key == "fractal_constant_factor" && value.find(' ') == std::string::npos)
    value = value + " " + value + " " + value;
  if (version <= 2.071)
    for (std::string_view k : kMaterialKeys)
      if (key == k) key = "mat1_" + key;
  if (version <= 2.071 && key == "fractal_color") key = "mat1_use_colors_from_palette";
  if (version < 2.12) replace_all(key, "gpu_", "opencl_");
  if (version < 2.19 && key.find("surface_color_palette") != std::string::npos) {
    replace_all(key, "surface_color_palette", "surface_color_gradient");
    value = palette_to_gradient(value);
  }
  if (version >= 2.25) {
    for (const Pair& p : kMainLight)
      if (key == p.newer) key = std::string(p.older);
    // lightN_x (N >= 2) was aux_light_x_(N-1).
    if (starts_with(key, "light") && key.size() > 7 && key[5] >= '2' && key[5] <= '9' && key[6] == '_')
      for (const Pair& p : kAuxLight)
        if (std::string_view(key).substr(7) == p.newer) {
          key = std::string(p.older) + std::to_string(key[5] - '1');
          break;
        }
  }
}

std::string current_key_name(const std::string& key, double version) {
  std::string k = key, v;
  apply_renames(k, v, version);
  return k;
}

}  // namespace sdfc::fract
