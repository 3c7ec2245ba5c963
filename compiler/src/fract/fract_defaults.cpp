// Mandelbulber 2.20's defaults for every key the importer reads, as
// `mandelbulber2 --list` prints them. A key of a numbered family
// (`formula_2`, `boolean_operator_5`) falls back to its `#` row; the rows
// that differ per index (`formula_1`, the aux lights) are listed by index.
#include <cctype>
#include <string>
#include <string_view>

#include "sdfc/fract/fract_params.hpp"

namespace sdfc::fract {
namespace {

struct Row {
  std::string_view key, value;
};

constexpr Row kMain[] = {
    // formulas and the hybrid / boolean sequence
    {"formula_1", "2"}, {"formula_#", "0"}, {"hybrid_fractal_enable", "0"}, {"boolean_operators", "0"},
    {"boolean_operator_#", "1"}, {"formula_iterations_#", "1"}, {"formula_start_iteration_#", "0"},
    {"formula_stop_iteration_#", "250"}, {"fractal_enable_#", "1"}, {"formula_position_#", "0 0 0"},
    {"formula_rotation_#", "0 0 0"}, {"formula_scale_#", "1"}, {"formula_repeat_#", "0 0 0"},
    {"formula_weight_#", "1"}, {"dont_add_c_constant_#", "0"}, {"julia_mode_#", "0"}, {"julia_c_#", "0 0 0"},
    {"fractal_constant_factor_#", "1 1 1"}, {"repeat_from", "1"},
    // the orbit
    {"julia_mode", "0"}, {"julia_c", "0 0 0"}, {"N", "250"}, {"bailout", "100"}, {"use_default_bailout", "1"},
    {"fractal_constant_factor", "1 1 1"}, {"fractal_rotation", "0 0 0"}, {"repeat", "0 0 0"},
    {"interior_mode", "0"}, {"iteration_threshold_mode", "0"}, {"limits_enabled", "0"}, {"limit_min", "-10 -10 -10"}, {"limit_max", "10 10 10"},
    {"constant_DE_threshold", "0"}, {"delta_DE_function", "0"}, {"smoothness", "1"},
    // camera and image
    {"camera", "3 -6 2"}, {"target", "0 0 0"}, {"camera_rotation", "26.565 -16.60154 0"}, {"camera_top", "-0.1277753 0.2555506 0.958314"}, {"fov", "1"},
    {"perspective_type", "0"}, {"image_width", "800"}, {"image_height", "600"}, {"detail_level", "1"},
    {"DE_factor", "1"}, {"view_distance_max", "50"}, {"legacy_coordinate_system", "0"}, {"stereo_enabled", "0"},
    {"DOF_enabled", "0"}, {"gamma", "1"}, {"brightness", "1"}, {"contrast", "1"}, {"hdr", "0"},
    // background
    {"background_color_1", "0000 95a2 ffff"}, {"background_color_2", "ffff ffff ffff"},
    {"background_color_3", "0000 2710 01f4"}, {"textured_background", "0"}, {"env_mapping_enable", "0"},
    // lights
    {"main_light_enable", "1"}, {"main_light_alpha", "-45"}, {"main_light_beta", "45"},
    {"main_light_colour", "ffff ffff ffff"}, {"main_light_intensity", "1"}, {"main_light_position_relative", "1"},
    {"shadows_enabled", "1"}, {"shadows_cone_angle", "1"}, {"fake_lights_enabled", "0"},
    {"aux_light_enabled_#", "0"}, {"aux_light_colour_1", "b2c1 d181 e86a"}, {"aux_light_colour_2", "f59b da0a c3a3"},
    {"aux_light_colour_3", "fd74 fda0 bed0"}, {"aux_light_colour_4", "cde0 f41c b256"},
    {"aux_light_intensity_1", "1.3"}, {"aux_light_intensity_2", "1"}, {"aux_light_intensity_3", "3"},
    {"aux_light_intensity_4", "2"}, {"aux_light_position_1", "3 -3 3"}, {"aux_light_position_2", "-3 -3 0"},
    {"aux_light_position_3", "-3 3 -1"}, {"aux_light_position_4", "0 -1 -3"},
    // effects
    {"ambient_occlusion_enabled", "0"}, {"ambient_occlusion", "1"}, {"ambient_occlusion_mode", "2"},
    {"ambient_occlusion_quality", "4"}, {"glow_enabled", "1"}, {"glow_intensity", "0.2"},
    {"glow_color_1", "a018 aea9 c152"}, {"basic_fog_enabled", "0"}, {"basic_fog_visibility", "20"},
    {"basic_fog_color", "e807 ef12 ffff"}, {"raytraced_reflections", "0"}, {"reflections_max", "5"},
    {"volumetric_fog_enabled", "0"}, {"iteration_fog_enable", "0"},
    // the first material
    {"mat1_surface_color", "c350 c350 c350"}, {"mat1_specular", "5"}, {"mat1_reflectance", "0"},
    {"mat1_use_colors_from_palette", "1"},
    {"mat1_surface_color_gradient",
     "0 fd6029 1000 698403 2000 fff59b 3000 f5bd22 4000 0b5e87 5000 c68876 6000 a51c64 7000 3b9fee 8000 d4ffd4 "
     "9000 aba53c"},
    {"mat1_coloring_speed", "1"}, {"mat1_coloring_palette_offset", "0"},
};

constexpr Row kFractal[] = {
    {"power", "9"}, {"alpha_angle_offset", "0"}, {"beta_angle_offset", "0"}, {"gamma_angle_offset", "0"},
    {"mandelbox_scale", "2"}, {"mandelbox_folding_limit", "1"}, {"mandelbox_folding_value", "2"},
    {"mandelbox_folding_min_radius", "0.5"}, {"mandelbox_folding_fixed_radius", "1"},
    {"mandelbox_offset", "0 0 0"}, {"mandelbox_rotations_enabled", "0"}, {"mandelbox_main_rotation_enabled", "0"},
    {"transf_scale_3", "3"},
    {"IFS_abs_x", "0"}, {"IFS_abs_y", "0"}, {"IFS_abs_z", "0"}, {"IFS_direction_#", "1 0 0"}, {"IFS_distance_#", "0"},
    {"IFS_edge", "0 0 0"}, {"IFS_edge_enabled", "0"}, {"IFS_enabled_#", "0"}, {"IFS_intensity_#", "1"},
    {"IFS_menger_sponge_mode", "0"}, {"IFS_offset", "1 0 0"}, {"IFS_rotation", "0 0 0"}, {"IFS_rotation_enabled", "0"},
    {"IFS_rotations_#", "0 0 0"}, {"IFS_scale", "2"}, {"mandelbox_rotation_main", "0 0 0"},
    {"transf_constant_multiplier_111", "1 1 1"}, {"transf_addition_constant", "0 0 0"}, {"transf_rotation_enabled", "0"},
    {"transf_function_enabledx_false", "0"}, {"transf_function_enabled_false", "0"},
    {"cadd", "-1.3"},  // aexion
    // the presets' keys (formula_presets*.cpp)
    {"transf_scale", "1"}, {"transf_scale_1", "1"}, {"transf_offset", "0"}, {"transf_addCpixel_enabled_false", "0"},
    {"transf_function_enabled", "1"}, {"transf_function_enabledz_false", "0"}, {"transf_function_enabledP_false", "0"},
    {"transf_function_enabledR_false", "0"}, {"transf_offset_1105", "1 1 0.5"}, {"transf_offset_0005", "0.005"},
    {"transf_function_enabledSw_false", "0"}, {"mandelbox_vary_scale_vary", "0"}, {"transf_minR2_p25", "0.25"},
    {"transf_maxR2_1", "1"}, {"transf_addition_constant_111", "1 1 1"}, {"transf_function_enabledy_false", "0"},
    {"transf_rotation", "0 0 0"}, {"transf_scaleG_1", "1"}, {"transf_function_enabledAx", "1"},
    {"transf_function_enabledAy", "1"}, {"transf_function_enabledAy_false", "0"},
    {"transf_function_enabledAz_false", "0"}, {"transf_function_enabledCz_false", "0"},
    {"transf_function_enabledCx_false", "0"}, {"transf_function_enabledBz_false", "0"},
    {"transf_function_enabledF_false", "0"}, {"transf_function_enabledAx_false", "0"},
    {"transf_sphere_inversion_enabled_false", "0"}, {"transf_function_enabledBy_false", "0"},
    {"transf_function_enabledBx_false", "0"}, {"transf_addition_constant_0777", "0.7 0.7 0.7"},
    {"transf_minimum_radius_05", "0.5"}, {"analyticDE_tweak_005", "0.05"}, {"analyticDE_scale_1", "1"},
    {"boxfold_bulbpow2_folding_factor", "2"}, {"boxfold_bulbpow2_z_factor", "5"},
};

template <size_t N>
const char* find(const Row (&rows)[N], std::string_view key) {
  for (const Row& r : rows)
    if (r.key == key) return r.value.data();
  return nullptr;
}

}  // namespace

const char* default_value(const std::string& key, bool fractal_section) {
  if (const char* v = fractal_section ? find(kFractal, key) : find(kMain, key)) return v;
  size_t end = key.size();  // KEY_N: the row KEY_#
  while (end > 0 && std::isdigit(static_cast<unsigned char>(key[end - 1]))) --end;
  if (end == key.size() || end == 0 || key[end - 1] != '_') return nullptr;
  std::string row = key.substr(0, end) + "#";
  return fractal_section ? find(kFractal, row) : find(kMain, row);
}

}  // namespace sdfc::fract
