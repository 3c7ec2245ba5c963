#pragma once
// The writers behind the formula table's rows, and the helpers they share.
// Internal to the importer.
#include <string>

#include "formula_table.hpp"

namespace sdfc::fract {

// "[fractal_N] KEY": where a value came from.
std::string from(const FormulaInput& in, const std::string& key);
// `iterations: N`, capped at `cap` (the comment says so).
Field iterations_field(const FormulaInput& in, int cap);
// Refuses dont_add_c_constant_N and a fractal_constant_factor other than 1.
void require_c_added(const FormulaInput& in);

// formula_chains.cpp: Mandelbulber's rotation angles (degrees) as rotate
// steps ("" or items ending in ", "); the step adding c (times
// fractal_constant_factor; "" when `adds` is false); whether the formula adds
// c (dont_add_c_constant_N against its default); julia_c times the factor.
std::string rotation2_steps(const Vec3& degrees, bool mirror = false);  // SetRotation2's order (Mandelbox, transf_rotation)
std::string rotation3_steps(const Vec3& degrees, bool mirror);          // SetRotation3's order (the IFS)
std::string add_c_step(const FormulaInput& in, bool adds);
bool adds_c(const FormulaInput& in, bool by_default);
Vec3 julia_constant(const FormulaInput& in);
// One formula alone as a `formula:` node of its chain.
Node chain_formula(const FormulaInput& in, const ChainPart& part);

ChainPart mandelbulb_chain(const FormulaInput& in);         // id 2, formula_bulbs.cpp
ChainPart mandelbulb_power2_chain(const FormulaInput& in);  // id 3
ChainPart mandelbox_chain(const FormulaInput& in);          // id 8, formula_chains.cpp
ChainPart menger_chain(const FormulaInput& in);             // id 7
ChainPart ifs_chain(const FormulaInput& in);                // id 10
Node mandelbulb(const FormulaInput& in);
Node mandelbulb_power2(const FormulaInput& in);
Node ifs(const FormulaInput& in);

// formula_presets.cpp: the formulas sdfc has as presets. Shared by their
// writers: refusing a switch that is on or a value that is not 0; one
// preset node with its fields, the iterations (capped), the bailout and,
// where c is added, the julia constant.
void require_off(const FormulaInput& in, const std::string& key);
void require_zero(const FormulaInput& in, const std::string& key);
Node preset_node(const FormulaInput& in, const char* preset, std::vector<Field> fields, int cap, bool julia = true);
// Mandelbulber's rotation angles `key` (degrees) as the presets'
// rotation_axis and rotation_angle when they turn about one axis (a turn
// about more is refused); `axes` is the axis each angle turns about.
void single_rotation(const FormulaInput& in, const std::string& key, const Vec3 (&axes)[3], std::vector<Field>& fields);
// CRotationMatrix::SetRotation2 (the transf_rotation of most formulas): x
// turns about x, y about y, z about z, in that order.
constexpr Vec3 kRotation2Axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

Node xenodreambuie(const FormulaInput& in);       // id 11, formula_presets.cpp
Node menger_mod1(const FormulaInput& in);         // id 61
Node eiffie_msltoe(const FormulaInput& in);       // id 70
Node menger_cross_kifs(const FormulaInput& in);   // id 98
Node menger_smooth(const FormulaInput& in);       // id 113
Node box_fold_bulb_pow2(const FormulaInput& in);  // id 16, formula_presets_box.cpp
Node pseudo_kleinian(const FormulaInput& in);     // id 103
Node abox_mod11(const FormulaInput& in);          // id 119
Node amazing_surf_mod2(const FormulaInput& in);   // id 132
ChainPart box_fold_bulb_pow2_chain(const FormulaInput& in);
ChainPart abox_mod11_chain(const FormulaInput& in);
ChainPart amazing_surf_mod2_chain(const FormulaInput& in);
Node quaternion_mandelbrot(const FormulaInput& in);  // id 5 without julia mode
Node hypercomplex(const FormulaInput& in);           // id 4
Node aexion(const FormulaInput& in);                 // id 19

}  // namespace sdfc::fract
